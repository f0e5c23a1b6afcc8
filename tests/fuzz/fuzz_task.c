/* fuzz_task.c - fuzzes the task reader (paper 2.3; task.h).
 *
 * Any bytes, as the TASK argument would give them (up to the first NUL):
 * task_parse either reads a task whose short form reads back to the same task, or
 * fails with one clear diagnostic. */
#include <string.h>

#include "fuzz.h"
#include "utak/base/task.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char text[512];
	size_t n = size < sizeof text - 1 ? size : sizeof text - 1;
	memcpy(text, data, n);
	text[n] = 0;
	Task t, again;
	Diag d;
	if (task_parse(text, &t, &d) != 0) {
		FUZZ_CHECK(fuzz_diag_ok(d.msg, "task"), "bad diagnostic '%s'", d.msg);
		return 0;
	}
	char form[64];
	task_short_form(&t, form, sizeof form);
	FUZZ_CHECK(task_parse(form, &again, &d) == 0, "short form '%s' does not read back", form);
	FUZZ_CHECK(memcmp(&t, &again, sizeof t) == 0, "short form '%s' reads back differently", form);
	return 0;
}
