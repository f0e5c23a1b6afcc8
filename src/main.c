/* main.c - the utak command (placeholder until the TABLETOP issue lands). */
#include <stdio.h>

int main(void)
{
	fprintf(stderr, "utak: not built yet\n");
	return 2;
}
