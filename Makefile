# recstab -- exact and certified stability of time-stepping schemes.
# Targets: deps all check demo install clean (see README.md).

CC      ?= cc
PREFIX  ?= /usr/local
BUILD   ?= build
CSTD    := -std=c11 -D_POSIX_C_SOURCE=200809L
WARN    := -Wall -Wextra -Werror -Wno-format-truncation
WARN    += -Wmissing-prototypes -Wstrict-prototypes -Wshadow
# gcc's stringop-overread misfires on FLINT's inline mpoly helpers
WARN    += $(if $(findstring clang,$(CC)),,-Wno-stringop-overread)
# FLINT 3.2 deprecates names FLINT 3.1 and 2.9 still use (flint_randinit...):
# a warning there, not a failed build
WARN    += -Wno-error=deprecated-declarations
OPT     ?= -O2 -g
SAN     ?=
# FLINT 3 (Arb is part of it: no -larb; flint.pc, every header in
# include/flint/, found as <flint/fmpz.h> and <arb.h>) when pkg-config finds
# it, else Debian's FLINT 2.9 + Arb 2.23 (no .pc files; Arb's library is
# -lflint-arb).  `make print-flint` shows the choice; tests/cli/suite_build.sh
# runs it with fake pkg-config programs (PKG_CONFIG=...).
PKG_CONFIG ?= pkg-config
FLINT3  := $(shell $(PKG_CONFIG) --atleast-version=3 flint 2>/dev/null && echo yes)
ifeq ($(FLINT3),yes)
FLINT_CFLAGS := $(shell $(PKG_CONFIG) --cflags flint) -I$(shell $(PKG_CONFIG) --variable=includedir flint)/flint
FLINT_LIBS   := $(shell $(PKG_CONFIG) --libs flint)
else
FLINT_CFLAGS := -I/usr/include/flint
FLINT_LIBS   := -lflint-arb -lflint
endif
# FLINT's headers are system headers to the build: FLINT 3's inline helpers
# have unused parameters that -Wextra -Werror would reject.
FLINT_INC := $(patsubst -I%,-isystem %,$(FLINT_CFLAGS))
DEP_LIBS := $(FLINT_LIBS) -lgsl -lgslcblas -ljansson -lmpfr -lgmp -lm
# -fPIC everywhere: the same objects make librecstab.a and librecstab.so
CFLAGS_ALL = $(CSTD) $(WARN) $(OPT) $(SAN) -fPIC -fopenmp -Iinclude -Isrc $(FLINT_INC) $(CFLAGS)
LIBS    := -fopenmp $(DEP_LIBS)
VERSION := 0.1.0
SOVERSION := 0
# Debian's python3 (python3-numpy, python3-pytest), not one earlier on PATH
PYTHON  ?= $(if $(wildcard /usr/bin/python3),/usr/bin/python3,python3)

# Debian packages, each with why (make prints the reason of each package it
# installs; `make deps-list` prints them all).  `make deps` installs what
# building, `make check` and `make demo` need; `make fuzz` and
# `make check-valgrind` add their own tools.
DEB_WHY := \
  libflint-dev:exact_polynomials,_FLINT libflint-arb-dev:certified_balls,_Arb \
  libgsl-dev:the_double_root_finder_of_sweeps libgmp-dev:big_integers libmpfr-dev:the_floats_of_Arb \
  libjansson-dev:JSON_documents libcmocka-dev:unit_tests_of_make_check gnuplot-nox:--plot \
  python3-pytest:make_check_tests_the_Python_package python3-numpy:numpy_arrays_of_maps_in_Python \
  python3-pandas:make_check_reads_every_CSV_file_with_pandas \
  texlive-latex-base:make_check_compiles_the_--latex_derivation_with_pdflatex \
  poppler-utils:make_check_reads_the_text_of_the_PDF_with_pdftotext
FUZZ_WHY := libclang-rt-14-dev:the_libFuzzer_runtime_of_make_fuzz clang:make_fuzz
VALGRIND_WHY := valgrind:make_check-valgrind
FLINT3_WHY := curl:make_check-flint3_fetches_FLINT_3_from_the_Debian_archive xz-utils:the_package_index_of_the_archive
STATIC_WHY := curl:make_static_fetches_FLINT_and_Arb_sources_from_the_Debian_archive dpkg-dev:dpkg-buildflags_gives_the_compiler_flags_of_Debian_builds
BENCH_WHY := qepcad:the_QEPCAD_B_peer_of_make_bench pari-gp:the_PARI_peer_of_make_bench mpsolve:the_MPSolve_peer_of_make_bench
DEB_PKGS := $(foreach p,$(DEB_WHY),$(firstword $(subst :, ,$(p))))

# $(call deb-install,WHO,PKG:WHY...): apt-get install of the missing ones,
# each named with its reason first
define deb-install
	@missing=""; for w in $(2); do p=$${w%%:*}; \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" \
	    || { missing="$$missing $$p"; echo "make $(1): installing $$p: $${w#*:}" | tr _ ' '; }; done; \
	if [ -n "$$missing" ]; then \
	  SUDO=""; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing >/dev/null \
	    || { echo "make $(1): apt-get failed for$$missing" >&2; exit 1; }; \
	else echo "make $(1): all Debian packages present"; fi
endef

# MPI build (make mpi): installed by `make mpi` only, not by `make deps`
MPI_PKGS := libopenmpi-dev openmpi-bin

# One folder per stage (docs/architecture.md); the library is every stage but
# cli.  File names are unique across folders (one archive, flat test binaries).
STAGES   := util lang lower algebra stability numeric analysis render
LIB_SRC  := $(sort $(foreach s,$(STAGES),$(wildcard src/$(s)/*.c)))
CLI_SRC  := $(sort $(wildcard src/cli/*.c))
TEST_SRC := $(sort $(wildcard tests/unit/*/test_*.c))
# the installed headers, an explicit list; private headers live in src/<stage>/
PUBLIC_HDRS := $(addprefix include/recstab/,recstab.h error.h budget.h str.h expr.h casefile.h \
               model.h scheme.h charpoly.h cond.h semisimple.h bilinear.h routh.h hurwitz.h positivity.h jury.h \
               rootcount.h radius.h cosim.h ladder.h sweep.h analysis.h report.h derivation.h api.h)
HDRS     := $(wildcard include/recstab/*.h src/*/*.h)

LIB_OBJ  := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(LIB_SRC))
CLI_OBJ  := $(patsubst src/%.c,$(BUILD)/obj/%.o,$(CLI_SRC))
TEST_BIN := $(addprefix $(BUILD)/tests/,$(basename $(notdir $(TEST_SRC))))
vpath test_%.c $(sort $(dir $(TEST_SRC)))

LIBRS  := $(BUILD)/librecstab.a
LIBSO_REAL := $(BUILD)/librecstab.so.$(VERSION)
LIBSO  := $(BUILD)/librecstab.so
BIN    := $(BUILD)/recstab
EXAMPLE_BIN := $(patsubst examples/%.c,$(BUILD)/examples/%,$(sort $(wildcard examples/*.c)))

.PHONY: all deps check test demo install clean check-sanitize check-flint3 bench static figures mpi print-public-headers examples deps-fuzz deps-valgrind deps-list print-flint

all: $(LIBRS) $(LIBSO) $(BIN) $(BUILD)/recstab.pc

# Install only the Debian packages that are missing (apt-get update first).
deps:
	$(call deb-install,deps,$(DEB_WHY))

deps-fuzz:
	$(call deb-install,fuzz,$(FUZZ_WHY))

deps-valgrind:
	$(call deb-install,check-valgrind,$(VALGRIND_WHY))

print-flint:
	@echo "FLINT3=$(FLINT3)"
	@echo "FLINT_CFLAGS=$(FLINT_CFLAGS)"
	@echo "FLINT_LIBS=$(FLINT_LIBS)"

deps-list:
	@for w in $(DEB_WHY) $(FUZZ_WHY) $(VALGRIND_WHY) $(FLINT3_WHY) $(STATIC_WHY) $(BENCH_WHY); do echo "$${w%%:*}: $${w#*:}" | tr _ ' '; done

$(BUILD)/obj/%.o: src/%.c $(HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -DRS_VERSION='"$(VERSION)"' -c $< -o $@

$(LIBRS): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

# the shared library: soname librecstab.so.$(SOVERSION), its dependencies
# recorded (DT_NEEDED) so that -lrecstab alone links a program
$(LIBSO_REAL): $(LIB_OBJ)
	$(CC) $(SAN) -shared -Wl,-soname,librecstab.so.$(SOVERSION) -Wl,--no-undefined -o $@ $^ $(LIBS)

$(LIBSO): $(LIBSO_REAL)
	ln -sf librecstab.so.$(VERSION) $(BUILD)/librecstab.so.$(SOVERSION)
	ln -sf librecstab.so.$(VERSION) $@

# recstab.pc for PREFIX (make install writes it again for its own PREFIX)
$(BUILD)/recstab.pc: recstab.pc.in Makefile
	@mkdir -p $(dir $@)
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@FLINT_CFLAGS@|$(FLINT_CFLAGS)|g' \
	    -e 's|@DEP_LIBS@|$(DEP_LIBS)|g' $< > $@

# the C examples, linked against the shared library in the build tree
$(BUILD)/examples/%: examples/%.c $(LIBSO) $(HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -o $@ $< -L$(BUILD) -lrecstab -Wl,-rpath,$(abspath $(BUILD)) $(LIBS)

examples: $(EXAMPLE_BIN)

# The command's link order (issue 13, start-up): libflint.so, libflint-arb.so
# and NTL are BIND_NOW, so every one of their ~10 500 symbol references is
# looked up at start-up along the global scope in link order: FLINT, Arb,
# then the libraries FLINT itself loads (NTL and its C++ runtime on Debian,
# found in libflint.so's DT_NEEDED; they would otherwise come last, after
# every other library) and GMP/MPFR first makes those look-ups short
# (`recstab --version`: 11.9 M -> 10.2 M instructions, callgrind).  The
# libraries are the same; only their order changes.
FLINT_SO := $(shell $(CC) -print-file-name=libflint.so)
FLINT_NEEDED := $(shell readelf -d $(FLINT_SO) 2>/dev/null | sed -n 's/.*Shared library: \[\(lib\(ntl\|stdc++\)\.so[.0-9]*\)\].*/-l:\1/p')
RUN_ORDER := -Wl,--push-state,--no-as-needed -lflint $(filter-out -lflint,$(filter -l%,$(FLINT_LIBS))) $(FLINT_NEEDED) -lgmp -lmpfr -Wl,--pop-state

$(BIN): $(CLI_OBJ) $(LIBRS)
	$(CC) $(CFLAGS_ALL) -o $@ $(CLI_OBJ) $(LIBRS) $(RUN_ORDER) $(LIBS)

$(BUILD)/tests/%: %.c tests/testutil.h tests/closed_forms.h $(LIBRS) $(HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -Itests -DRS_SOURCE_DIR='"$(CURDIR)"' -o $@ $< $(LIBRS) -lcmocka $(LIBS)

test: $(TEST_BIN) $(BIN) $(LIBSO) $(EXAMPLE_BIN)
	@BUILD=$(BUILD) sh tests/run.sh

check: deps
	@$(MAKE) --no-print-directory all
	@$(MAKE) --no-print-directory test

# Sanitizer build in its own tree; runs the whole suite and every case.
check-sanitize: deps
	@ASAN_OPTIONS=$(FUZZ_ASAN_OPTIONS) $(MAKE) --no-print-directory BUILD=build-san OPT="-O1 -g" \
	  SAN="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined" test

# The whole suite built against a real FLINT 3 (Debian trixie's packages,
# fetched and unpacked under build-flint3/, not installed): tests/flint3.sh.
check-flint3: deps
	$(call deb-install,check-flint3,$(FLINT3_WHY))
	@sh tests/flint3.sh

# The Park case's printed claims are refuted, so recstab exits 1 there by
# design (an expectation failed); only 2 and 3 make the demo fail.
demo: deps
	@$(MAKE) --no-print-directory all
	@$(BIN) cases/park-staggered.case; rc=$$?; [ $$rc -le 1 ] || exit $$rc

# build/recstab-static (`make static`; issue 17, then issue 13): the command
# linked fully static -- no dynamic loader, no shared object to map or
# relocate at start-up (bench/README.md has the figures).  Debian ships no
# libflint.a or libflint-arb.a, so bench/static_libs.sh builds them once from
# Debian's source packages of the installed versions (checksums from the
# .dsc; a few minutes, cached under $(BUILD)/static-libs; never run by `make
# all` or `make check`).  GMP, MPFR, GSL, CBLAS, jansson, OpenMP's runtime and
# glibc are Debian's lib*.a: one copy of GMP, whose allocator budget.c counts
# for FLINT and GMP alike.  Linked without -fopenmp (which would add the
# shared libgomp).  The objects are build/recstab's, compiled against
# Debian's FLINT 2.9 + Arb headers, the same versions as the static
# libraries; not for a FLINT 3 build (FLINT3=yes).  build/recstab itself is
# unchanged.
STATIC_ROOT := $(BUILD)/static-libs/root
STATIC_DEP_LIBS := -static -L$(STATIC_ROOT)/lib -larb -lflint -lgsl -lgslcblas -ljansson -lgomp -lmpfr -lgmp -lm -lpthread
static: $(BUILD)/recstab-static

$(STATIC_ROOT)/.done:
	@[ "$(FLINT3)" != yes ] || { echo "make static: needs Debian's FLINT 2.9 + Arb (FLINT3=yes here)" >&2; exit 1; }
	$(call deb-install,static,$(STATIC_WHY))
	OUT=$(BUILD)/static-libs sh bench/static_libs.sh

$(BUILD)/recstab-static: $(CLI_OBJ) $(LIBRS) $(STATIC_ROOT)/.done
	$(CC) $(filter-out -fopenmp,$(CFLAGS_ALL)) -o $@ $(CLI_OBJ) $(LIBRS) $(STATIC_DEP_LIBS)

# the in-process Park bench (issue 17): the one-call API N times in one
# process, beside SymPy's in-process figure (bench/run.sh, part (c'))
$(BUILD)/park_inprocess: bench/park_inprocess.c $(LIBRS) $(HDRS)
	$(CC) $(CFLAGS_ALL) -o $@ $< $(LIBRS) $(LIBS)

bench: all $(BUILD)/park_inprocess $(BUILD)/recstab-static
	$(call deb-install,bench,$(BENCH_WHY))
	sh bench/run.sh
	sh bench/bench_qepcad.sh
	sh bench/bench_qepcad_cfl.sh

# Python's site folder under PREFIX (Debian's python3 searches
# PREFIX/lib/python3.X/dist-packages for PREFIX=/usr/local)
PYDIR ?= $(PREFIX)/lib/$(shell $(PYTHON) -c 'import sys; print("python%d.%d" % sys.version_info[:2])' 2>/dev/null || echo python3)/dist-packages

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib \
	  $(DESTDIR)$(PREFIX)/include/recstab $(DESTDIR)$(PREFIX)/lib/pkgconfig \
	  $(DESTDIR)$(PREFIX)/share/man/man1 $(DESTDIR)$(PYDIR)/recstab
	install -m 755 $(BIN) $(DESTDIR)$(PREFIX)/bin/recstab
	install -m 644 $(LIBRS) $(DESTDIR)$(PREFIX)/lib/librecstab.a
	install -m 755 $(LIBSO_REAL) $(DESTDIR)$(PREFIX)/lib/librecstab.so.$(VERSION)
	ln -sf librecstab.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/librecstab.so.$(SOVERSION)
	ln -sf librecstab.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/librecstab.so
	install -m 644 $(PUBLIC_HDRS) $(DESTDIR)$(PREFIX)/include/recstab/
	install -m 644 recstab.1 $(DESTDIR)$(PREFIX)/share/man/man1/recstab.1
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@FLINT_CFLAGS@|$(FLINT_CFLAGS)|g' \
	    -e 's|@DEP_LIBS@|$(DEP_LIBS)|g' recstab.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/recstab.pc
	install -m 644 python/recstab/*.py $(DESTDIR)$(PYDIR)/recstab/
	echo 'LIBRARY = "$(PREFIX)/lib/librecstab.so.$(SOVERSION)"' > $(DESTDIR)$(PYDIR)/recstab/_installed.py

# build/recstab-mpi: the same sources with -DRS_MPI (mpicc); sweeps and maps
# are split over the ranks of `mpirun -n K build/recstab-mpi ...`.
MPI_OBJ := $(patsubst src/%.c,$(BUILD)/mpi-obj/%.o,$(LIB_SRC) $(CLI_SRC))

mpi:
	@missing=""; for p in $(MPI_PKGS); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" \
	    || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "make mpi: installing$$missing"; \
	  SUDO=""; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq $$missing >/dev/null \
	    || { echo "make mpi: apt-get failed for$$missing" >&2; exit 1; }; fi
	@$(MAKE) --no-print-directory $(BUILD)/recstab-mpi

$(BUILD)/mpi-obj/%.o: src/%.c $(HDRS)
	@mkdir -p $(dir $@)
	mpicc $(CFLAGS_ALL) -DRS_MPI -DRS_VERSION='"$(VERSION)"' -c $< -o $@

$(BUILD)/recstab-mpi: $(MPI_OBJ)
	mpicc $(CFLAGS_ALL) -o $@ $(MPI_OBJ) $(LIBS)

clean:
	rm -rf build build-san build-flint3

# ---- robustness: fuzzing, valgrind, the long property run -----------------
# make fuzz [FUZZ_SECONDS=60]: libFuzzer (clang, ASan+UBSan), one job, each
# harness in turn for FUZZ_SECONDS seconds (so the whole run takes about
# 3 x FUZZ_SECONDS plus the build):
#   fuzz_case      the case parser, expression engine and a charpoly run
#   fuzz_analyses  whole case files; their analyse/expect/claim lines pick the
#                  analyses; text report, Markdown, LaTeX and JSON rendered
#   fuzz_options   a bundled case + one analysis + fuzzed options (see the file)
# Seeds are every file in cases/, tests/bad/, tests/fuzz/regress/ and
# tests/fuzz/seeds/HARNESS/; each corpus grows in build/fuzz-corpus/HARNESS/;
# crashes/leaks/timeouts land in build/fuzz-artifacts/ (named HARNESS-crash-...).
# Every harness runs even when one fails; the target fails if any did.
# FUZZ_HARNESSES="fuzz_options" runs a subset.
FUZZ_SECONDS   ?= 60
FUZZ_CC        ?= clang
FUZZ_HARNESSES ?= fuzz_case fuzz_analyses fuzz_options
FUZZ_FLAGS     := -g -O1 -std=c11 -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc $(FLINT_CFLAGS) \
                  -DRS_SOURCE_DIR='"$(CURDIR)"' -DRS_VERSION='"$(VERSION)"'
FUZZ_LIBS      := $(DEP_LIBS)
FUZZ_OBJ       := $(patsubst src/%.c,build/fuzz-obj/%.o,$(LIB_SRC))
FUZZ_BINS      := $(addprefix build/,$(FUZZ_HARNESSES))

.PHONY: fuzz fuzz-build check-valgrind check-long

# the library once, instrumented for the fuzzers; each harness links it
build/fuzz-obj/%.o: src/%.c $(HDRS)
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link,address,undefined -c $< -o $@

build/fuzz_%: tests/fuzz/fuzz_%.c tests/fuzz/fuzz_common.h $(FUZZ_OBJ) $(HDRS)
	$(FUZZ_CC) $(FUZZ_FLAGS) -Wall -Wextra -Werror -fsanitize=fuzzer,address,undefined $< $(FUZZ_OBJ) -o $@ $(FUZZ_LIBS)

fuzz-build: $(FUZZ_BINS)
.SECONDARY: $(FUZZ_OBJ)

# The harnesses run each input under a 5 s budget (FUZZ_TIME_LIMIT).  One
# FLINT call the budget cannot interrupt lasts up to about a second natively
# (an inverse in a degree-28 number field at an algebraic region endpoint:
# 0.4 s) and ten times that under ASan with coverage, so an input counts as a
# hang past 25 s.  ASan's allocator keeps freed GMP blocks in its quarantine
# and caches (2.1 GB RSS for a run whose live heap is 16 MB natively): a
# smaller quarantine, released to the system, keeps -rss_limit_mb meaningful.
FUZZ_TIMEOUT ?= 25
FUZZ_ASAN_OPTIONS ?= quarantine_size_mb=32:allocator_release_to_os_interval_ms=200
fuzz: deps deps-fuzz fuzz-build
	@mkdir -p build/fuzz-artifacts
	@fail=""; for h in $(FUZZ_HARNESSES); do \
	  mkdir -p build/fuzz-corpus/$$h; \
	  for f in $$(find cases tests/bad tests/fuzz/regress tests/fuzz/seeds/$$h -type f 2>/dev/null); do \
	    cp "$$f" "build/fuzz-corpus/$$h/seed-$$(echo "$$f" | tr / _)"; done; \
	  echo "== $$h: $(FUZZ_SECONDS) s"; \
	  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=$(FUZZ_ASAN_OPTIONS) \
	    build/$$h -max_total_time=$(FUZZ_SECONDS) \
	    -max_len=4096 -timeout=$(FUZZ_TIMEOUT) -rss_limit_mb=2048 -dict=tests/fuzz/case.dict -print_final_stats=1 \
	    -artifact_prefix=build/fuzz-artifacts/$$h- build/fuzz-corpus/$$h || fail="$$fail $$h"; \
	done; \
	if [ -n "$$fail" ]; then echo "make fuzz: findings in$$fail (see build/fuzz-artifacts/)"; exit 1; fi

# Every case under valgrind (definite leaks and memory errors fail, exit 99);
# each case must still end with its "# expect-exit: N" status (default 0).
check-valgrind: deps deps-valgrind
	@$(MAKE) --no-print-directory all
	@fail=0; for f in $$(find cases -name '*.case' | sort); do \
	  want=$$(sed -n 's/^# expect-exit: *\([0-9]\).*/\1/p' "$$f" | head -1); want=$${want:-0}; \
	  valgrind -q --leak-check=full --errors-for-leak-kinds=definite --error-exitcode=99 \
	    $(BIN) "$$f" >/dev/null 2>$(BUILD)/valgrind.log; rc=$$?; \
	  if [ $$rc = $$want ]; then echo "valgrind ok $$f"; \
	  else echo "valgrind FAIL $$f: exit $$rc (expected $$want)"; cat $(BUILD)/valgrind.log; fail=1; fi; \
	done; exit $$fail

check-long: $(BUILD)/tests/test_property
	RS_PROPERTY_N=100000 $(BUILD)/tests/test_property

# recstab's versions of the source documents' figures (docs/figures/)
figures: deps
	@$(MAKE) --no-print-directory all
	sh docs/make-figures.sh

print-public-headers:   # for tests/cli/suite_headers.sh
	@echo $(PUBLIC_HDRS)
