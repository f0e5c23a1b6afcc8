/* replay.c - runs a fuzz harness over files, without libFuzzer (issue 6).
 *
 *   replay_NAME FILE...
 *
 * Linked with one harness (tests/fuzz/fuzz_NAME.c) and built by any C compiler
 * under ASan + UBSan, so that `make check` replays every seed and every input a
 * fuzzer ever crashed on (tests/fuzz/regress/NAME/) on machines without clang's
 * fuzzer runtime. A broken promise aborts, as under the fuzzer. Prints
 * "[PASS] replay NAME: N inputs". */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

int main(int argc, char **argv)
{
	int n = 0;
	for (int i = 1; i < argc; i++) {
		FILE *f = fopen(argv[i], "rb");
		if (!f) {
			fprintf(stderr, "replay: cannot open %s\n", argv[i]);
			return 1;
		}
		size_t cap = 1 << 16, len = 0, got;
		uint8_t *buf = malloc(cap);
		while (buf && (got = fread(buf + len, 1, cap - len, f)) > 0) {
			len += got;
			if (len == cap)
				buf = realloc(buf, cap *= 2);
		}
		fclose(f);
		if (!buf)
			abort();
		/* A copy of exactly len bytes, so ASan sees any read past the input. */
		uint8_t *copy = malloc(len ? len : 1);
		memcpy(copy, buf, len);
		free(buf);
		LLVMFuzzerTestOneInput(copy, len);
		free(copy);
		n++;
	}
	printf("[PASS] replay %s: %d inputs\n", argc > 0 ? argv[0] : "?", n);
	return 0;
}
