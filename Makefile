# Makefile - builds utak, its tests and its benchmarks (GNU make).
#
#   make            ./utak, optimised, with the warning list below and no warnings
#   make check      everything again with AddressSanitizer + UBSan, then every test
#   make bench      the path-finding benchmark on ../shared/data/movingai
#   make golden     regenerate golden files (a deliberate act: read the diff)
#
# Sources are found by wildcard: a new module is a new src/NAME.c and
# include/utak/NAME.h, and a new unit test is a new tests/unit/test_NAME.c.

CC      ?= cc
PREFIX  ?= /usr/local
DESTDIR ?=

# -ffp-contract=off: no fused multiply-add, so printed numbers do not depend on
# the compiler's choice of instructions (Box2D does the same).
WARN    = -Wall -Wextra -pedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
          -Wpointer-arith -Wcast-qual -Wvla
CSTD    = -std=c11 -D_POSIX_C_SOURCE=200809L -ffp-contract=off
CFLAGS  ?= -O2 -g
ALLCFLAGS = $(CSTD) $(WARN) -Iinclude $(CFLAGS)
LDLIBS  = -lm

SAN     = -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
CHECKFLAGS = $(CSTD) $(WARN) -Iinclude -O1 -g $(SAN)

LIBSRC  = $(filter-out src/main.c,$(wildcard src/*.c))
UNITSRC = $(wildcard tests/unit/test_*.c)

OBJ      = $(LIBSRC:src/%.c=build/rel/%.o)
CHECKOBJ = $(LIBSRC:src/%.c=build/chk/%.o)
UNITBIN  = $(UNITSRC:tests/unit/%.c=build/chk/unit/%)

all: utak

utak: build/rel/main.o build/rel/libutak.a
	$(CC) $(ALLCFLAGS) -o $@ build/rel/main.o build/rel/libutak.a $(LDLIBS)

build/rel/libutak.a: $(OBJ)
	rm -f $@; ar rcs $@ $(OBJ)

build/rel/%.o: src/%.c $(wildcard include/utak/*.h) | build/rel
	$(CC) $(ALLCFLAGS) -c -o $@ $<

build/chk/%.o: src/%.c $(wildcard include/utak/*.h) | build/chk
	$(CC) $(CHECKFLAGS) -c -o $@ $<

build/chk/libutak.a: $(CHECKOBJ)
	rm -f $@; ar rcs $@ $(CHECKOBJ)

build/chk/utak: build/chk/main.o build/chk/libutak.a
	$(CC) $(CHECKFLAGS) -o $@ build/chk/main.o build/chk/libutak.a $(LDLIBS)

build/chk/unit/%: tests/unit/%.c $(wildcard tests/unit/*.h) build/chk/libutak.a | build/chk/unit
	$(CC) $(CHECKFLAGS) -Itests/unit -o $@ $< build/chk/libutak.a $(LDLIBS)

build/rel build/chk build/chk/unit:
	mkdir -p $@

check: build/chk/utak $(UNITBIN)
	sh tests/run.sh build/chk/utak $(UNITBIN)

golden: utak
	sh tests/regen.sh ./utak

BENCHSRC = $(wildcard bench/*.c)
BENCHBIN = $(BENCHSRC:bench/%.c=build/rel/bench/%)

build/rel/bench/%: bench/%.c build/rel/libutak.a | build/rel/bench
	$(CC) $(ALLCFLAGS) -o $@ $< build/rel/libutak.a $(LDLIBS)

build/rel/bench:
	mkdir -p $@

bench: $(BENCHBIN)
	sh bench/run.sh

install: utak
	mkdir -p $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1 $(DESTDIR)$(PREFIX)/share/man/man5
	cp utak $(DESTDIR)$(PREFIX)/bin/
	cp man/utak.1 $(DESTDIR)$(PREFIX)/share/man/man1/
	cp man/utak.5 $(DESTDIR)$(PREFIX)/share/man/man5/

format:
	clang-format -i src/*.c include/utak/*.h tests/unit/*.c tests/unit/*.h

clean:
	rm -rf build utak

.PHONY: all check golden bench install format clean
.SUFFIXES:
