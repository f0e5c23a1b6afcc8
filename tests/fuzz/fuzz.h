/* fuzz.h - what every fuzz harness shares: the libFuzzer entry point and a check
 * that aborts, so that libFuzzer records the input as a crash.
 *
 * A harness is one file, tests/fuzz/fuzz_NAME.c, built by `make fuzz` under
 * AddressSanitizer and UndefinedBehaviorSanitizer, seeded from
 * tests/fuzz/corpus/NAME/ and run by tests/fuzz/run.sh. It feeds the bytes to a
 * reader as if a user had written them, and checks what the reader promises
 * (man utak.5, act.h): success, or one printable line of diagnostic. */
#ifndef UTAK_FUZZ_H
#define UTAK_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* FUZZ_CHECK(cond, ...): a broken promise is a crash, with the reason on stderr. */
#define FUZZ_CHECK(cond, ...)                                                            \
	do {                                                                             \
		if (!(cond)) {                                                           \
			fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, \
				#cond);                                                  \
			fprintf(stderr, __VA_ARGS__);                                    \
			fputc('\n', stderr);                                             \
			abort();                                                         \
		}                                                                        \
	} while (0)

/* fuzz_diag_ok(msg, prefix): a diagnostic is one non-empty line of printable
 * ASCII that names where the fault is, starting with prefix (the file's name, or
 * "--act"). It reaches a terminal: no control bytes, no raw input bytes. */
static inline int fuzz_diag_ok(const char *msg, const char *prefix)
{
	size_t i = 0;
	for (; prefix[i]; i++)
		if (msg[i] != prefix[i])
			return 0;
	if (!msg[i])
		return 0;
	for (; msg[i]; i++)
		if ((unsigned char)msg[i] < 0x20 || (unsigned char)msg[i] > 0x7e)
			return 0;
	return 1;
}

#endif
