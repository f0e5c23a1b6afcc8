/* fuzz_act.c - fuzzes the reader of motor-command scripts given to --act (paper 2.2; act.h).
 *
 * Any bytes: act_parse either fails with one clear diagnostic and no commands, or
 * gives at most ACT_MAX_COMMANDS commands of the five kinds with finite numbers
 * within ACT_MAX_MAGNITUDE. */
#include <math.h>

#include "fuzz.h"
#include "utak/body/act.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	MotorCommand *cmds;
	int count;
	Diag d;
	if (act_parse((const char *)data, size, &cmds, &count, &d) != 0) {
		FUZZ_CHECK(fuzz_diag_ok(d.msg, "--act"), "bad diagnostic '%s'", d.msg);
		FUZZ_CHECK(cmds == NULL && count == 0, "a failed script left %d commands", count);
		return 0;
	}
	FUZZ_CHECK(count >= 0 && count <= ACT_MAX_COMMANDS, "%d commands", count);
	FUZZ_CHECK(count == 0 || cmds != NULL, "no array for %d commands", count);
	for (int i = 0; i < count; i++) {
		const MotorCommand *c = &cmds[i];
		FUZZ_CHECK(c->kind >= MOTOR_MOVE && c->kind <= MOTOR_RELEASE, "kind %d", (int)c->kind);
		FUZZ_CHECK(isfinite(c->dx) && isfinite(c->dy) && isfinite(c->deg), "command %d not finite", i);
		FUZZ_CHECK(fabs(c->dx) <= ACT_MAX_MAGNITUDE && fabs(c->dy) <= ACT_MAX_MAGNITUDE &&
				   fabs(c->deg) <= ACT_MAX_MAGNITUDE,
			   "command %d too large", i);
	}
	free(cmds);
	return 0;
}
