# The one entry point of the teaching ray tracer.  `make help` lists the targets.
#
# Chapters are found by directory: chapters/NN_name/.  Chapter N's renderer
# links common/ and the stage files (every .c but render.c, with renderer/
# and scenes/) of chapters 1..N.
# A stage file that has exercises exists twice: the complete version in
# solutions/NN_name/ and the student's skeleton in chapters/NN_name/.  By
# default every build takes the solutions; STUDENT=1 takes the skeletons.
#
# A student's copy (`make handout`) has no solutions/: there the reference
# versions of the exercise files are compiled libraries,
# reference/REAL/libNN_name.a, and the default build is STUDENT=1.

.DEFAULT_GOAL := all
SHELL := /bin/bash
.DELETE_ON_ERROR:
.SECONDARY:
.SUFFIXES:

CC ?= cc
REAL ?= double
# A student's copy: no solution source, the compiled reference libraries instead.
HANDOUT := $(if $(wildcard solutions/[0-9][0-9]_*/*.c),,$(if $(wildcard reference/*/lib[0-9][0-9]_*.a),1))
STUDENT ?= $(if $(HANDOUT),1,0)
WERROR ?= -Werror
# REFERENCE="01 02": a student's build takes these chapters from the reference.
REFERENCE ?=
SANITIZE ?= 0
OPT ?= -O2 -g

# V=1 shows every command and each suite's whole output.  By default a
# compile shows only its warnings and errors, each program built one line
# ("  LINK    path"), and each test suite one line (its output goes to a log
# that is named when it fails: tools/run-tests.sh).
V ?= 0
Q := $(if $(filter 1,$(V)),,@)
# (make -s prints nothing at all.)
QLINK = $(if $(Q),@$(if $(findstring s,$(firstword -$(MAKEFLAGS))),,echo "  LINK    $@";))

ifeq ($(filter $(REAL),double float),)
$(error REAL must be double or float, not '$(REAL)')
endif

# clang builds into build-clang/, another gcc than the default (CC=gcc-11) into build-gcc-11/.
compiler := $(if $(findstring clang,$(CC)),-clang,$(if $(filter-out cc gcc,$(notdir $(CC))),-$(notdir $(CC))))
variant := $(compiler)$(if $(filter float,$(REAL)),-float)$(if $(filter 1,$(SANITIZE)),-asan)$(if $(filter 1,$(STUDENT)),-student)$(if $(filter 1,$(STUDENT)),$(if $(strip $(REFERENCE)),-ref$(subst $(eval) ,,$(strip $(REFERENCE)))))
BUILD ?= build$(variant)

CPPFLAGS := -D_POSIX_C_SOURCE=200809L -I common -I chapters -I tests -I /usr/include/stb \
            $(if $(filter float,$(REAL)),-DRT_REAL_FLOAT)
SANITIZERS := -fsanitize=address -fsanitize=undefined -fsanitize=float-cast-overflow
CFLAGS := -std=c11 -Wall -Wextra -Wpedantic $(WERROR) -ffp-contract=off -fopenmp $(OPT) -MMD -MP \
          $(if $(filter 1,$(SANITIZE)),$(SANITIZERS) -fno-sanitize-recover=all -fno-omit-frame-pointer)
LDFLAGS := -fopenmp $(if $(filter 1,$(SANITIZE)),$(SANITIZERS))
LDLIBS := -lstb -lexpat -lm

CHAPTERS := $(sort $(notdir $(patsubst %/,%,$(wildcard chapters/[0-9][0-9]_*/))))
COMMON_SRC := $(sort $(wildcard common/*.c))

# $(call num,01_camera_rays) -> 01
num = $(firstword $(subst _, ,$1))
# CHAPTER and REFERENCE name chapters of this copy (01 or 01_camera_rays):
# anything else is an error, never an empty selection.
$(foreach x,$(CHAPTER) $(REFERENCE),$(if $(filter $x,$(CHAPTERS) $(foreach c,$(CHAPTERS),$(call num,$c))),,\
    $(error no chapter '$x' in this copy (CHAPTER and REFERENCE take 01 or 01_camera_rays; chapters: $(CHAPTERS)))))
# The chapters up to and including $1.
upto = $(foreach c,$(CHAPTERS),$(if $(filter $(call num,$c),$(firstword $(sort $(call num,$c) $(call num,$1)))),$c))
# The exercise files of chapter $1 (FILE.c): those that have a solution, or
# in a student's copy the members of the chapter's reference library.
REFERENCE_DIR := reference/$(REAL)
$(foreach c,$(CHAPTERS),$(eval EXERCISES_$c := $(if $(HANDOUT),$(patsubst %.o,%.c,$(shell ar t $(REFERENCE_DIR)/lib$c.a 2>/dev/null)),$(notdir $(wildcard solutions/$c/*.c)))))
# The reference version of chapter $1's exercise files: the solutions' objects,
# or in a student's copy the compiled library.
reference = $(if $(EXERCISES_$1),$(if $(HANDOUT),$(REFERENCE_DIR)/lib$1.a,$(call objs,$(addprefix solutions/$1/,$(EXERCISES_$1)))))
# The objects of chapter $1's stage files: the student's exercise files when $2
# is 1, else the reference.
stage_objs = $(call objs,$(filter-out $(if $(filter 1,$2),,$(addprefix chapters/$1/,$(EXERCISES_$1))),$(sort $(filter-out %/render.c,$(wildcard chapters/$1/*.c chapters/$1/renderer/*.c chapters/$1/scenes/*.c))))) $(if $(filter 1,$2),,$(call reference,$1))
# The stage objects of chapters 1..$1.
stages_upto = $(foreach c,$(call upto,$1),$(call stage_objs,$c,$(if $(filter $c $(call num,$c),$(REFERENCE)),0,$(STUDENT))))
# Links the prerequisites $1: every member of a reference library is linked,
# exactly as the solutions' objects would be.
comma := ,
link = $(CC) $(LDFLAGS) $(filter %.o,$1) $(if $(filter %.a,$1),-Wl$(comma)--whole-archive $(filter %.a,$1) -Wl$(comma)--no-whole-archive) $(LDLIBS)
objs = $(patsubst %.c,$(BUILD)/obj/%.o,$1)

TEST_SUPPORT := tests/suite.c tests/answers.c tests/image_compare.c
# A chapter's checks of inputs drawn at grading time (tests/answers.h), when it has them.
seeded = $(wildcard tests/seeded/$1.c)
# Suites of common/ link common/ only; a chapter's suite links its stages.
COMMON_TESTS := $(sort $(basename $(notdir $(wildcard tests/test_common_*.c))))
CHAPTER_TESTS := $(foreach c,$(CHAPTERS),$(if $(wildcard tests/test_$c.c),test_$c))
# The fuzz corpus replay (tests/test_fuzz_corpus.c) links the fuzz targets of
# fuzz/ (a copy of the project without fuzz/ has no replay).
FUZZ_TARGETS := scene obj options texture
# Cross-chapter suites (the course's scenes) link every chapter and are not graded.
CROSS_TESTS := $(if $(wildcard tests/test_scenes.c),test_scenes)
# The grader's verdict (tools/judge.c) has a suite of its own.
TOOLS_TESTS := $(if $(wildcard tests/test_tools_judge.c),test_tools_judge)
ALL_TESTS := $(COMMON_TESTS) $(CHAPTER_TESTS) $(CROSS_TESTS) $(if $(wildcard fuzz/fuzz.h),test_fuzz_corpus) $(TOOLS_TESTS)

# Labs: chapters/NN_name/lab/ holds what measures or proves the lesson beside
# it (counts, tables, sweeps, heat maps, the fast grid).  A lab is its own
# program, BUILD/NN_name/lab, from lab/main.c, the lab's other files and the
# stages of chapters 1..N; its suite tests/lab_NN_name.c links the same.  The
# lesson never reads the lab: no stage file or renderer includes lab/.  The
# chapter's graded suite links the lab's files too (not its main.c), so that a
# test may measure the student's code with the lab's harness (chapter 06's
# acne and leaks).
LAB_CHAPTERS := $(foreach c,$(CHAPTERS),$(if $(wildcard chapters/$c/lab/main.c),$c))
lab_objs = $(call objs,$(sort $(filter-out %/main.c,$(wildcard chapters/$1/lab/*.c))))
LAB_TESTS := $(foreach c,$(LAB_CHAPTERS),$(if $(wildcard tests/lab_$c.c),lab_$c))
ALL_TESTS += $(LAB_TESTS)

RENDERERS := $(foreach c,$(CHAPTERS),$(BUILD)/$c/render) $(foreach c,$(LAB_CHAPTERS),$(BUILD)/$c/lab)
include tests/explain.mk
TEST_BINS := $(addprefix $(BUILD)/tests/,$(ALL_TESTS))
# The built-in scenes' images: one folder per build variant, as build/ is:
# out/, out-float/, out-clang/, out-student/, out-student-ref01/, ...
OUT := out$(variant)
IMAGES := $(foreach c,$(CHAPTERS),$(OUT)/$c.png)

.PHONY: all renderers tests test test-suites deps help clean skeletons check-skeletons grade grade-run autograder \
        handout handout-libs reference-libs \
        figure-renderers figures check-figures snippets check-snippets outputs check-outputs check-lessons check-links check fuzz fuzz-build deps-fuzz \
        test-extremes check-grid-images globe-texture check-seeded
all: renderers $(if $(filter 1,$(SANITIZE)),,$(IMAGES))
renderers: $(RENDERERS)
tests: $(TEST_BINS)

# ---- compiling and linking ----------------------------------------------------

deps:
	@tools/deps.sh "$(CC)"

# COMPILE_AS=user (set by grade-run for the autograder) compiles the files of
# chapters/ as that user (tools/compile-as.sh).
COMPILE_AS ?=
$(BUILD)/obj/%.o: %.c | deps
	@mkdir -p $(@D)
	$(Q)$(if $(and $(COMPILE_AS),$(filter chapters/%,$<)),tools/compile-as.sh $(COMPILE_AS) $@ $<) $(CC) $(CPPFLAGS) $(CFLAGS) \
	    $(if $(and $(COMPILE_AS),$(filter chapters/%,$<)),,-c $< -o $@)

define chapter_rules
$(BUILD)/$1/render: $(call objs,chapters/$1/render.c) $(call stages_upto,$1) $(call objs,$(COMMON_SRC))
	@mkdir -p $$(@D)
	$$(QLINK)$$(call link,$$^) -o $$@

$(OUT)/$1.png: $(BUILD)/$1/render
	@mkdir -p $(OUT)
	$(Q)$(BUILD)/$1/render -o $$@

$(BUILD)/tests/test_$1: $(call objs,tests/test_$1.c $(TEST_SUPPORT) $(call seeded,$1)) $(call stages_upto,$1) $(call lab_objs,$1) $(call objs,$(COMMON_SRC))
	@mkdir -p $$(@D)
	$$(QLINK)$$(call link,$$^) -lcmocka -o $$@

$(BUILD)/$1/lab: $(call objs,chapters/$1/lab/main.c) $(call lab_objs,$1) $(call stages_upto,$1) $(call objs,$(COMMON_SRC))
	@mkdir -p $$(@D)
	$$(QLINK)$$(call link,$$^) -o $$@

$(BUILD)/tests/lab_$1: $(call objs,tests/lab_$1.c $(TEST_SUPPORT)) $(call lab_objs,$1) $(call stages_upto,$1) $(call objs,$(COMMON_SRC))
	@mkdir -p $$(@D)
	$$(QLINK)$$(call link,$$^) -lcmocka -o $$@

# The library of chapter $1's reference objects, for a student's copy.
$(BUILD)/reference/lib$1.a: $(call objs,$(addprefix solutions/$1/,$(EXERCISES_$1)))
	@mkdir -p $$(@D)
	$(Q)rm -f $$@ && ar rcs $$@ $$^
endef
$(foreach c,$(CHAPTERS),$(eval $(call chapter_rules,$c)))

# Chapter 11's lab suite fails the build's allocations on purpose (tests/lab_11_grid.c, test_out_of_memory).
$(BUILD)/tests/lab_11_grid: LDFLAGS += -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc

$(BUILD)/tests/test_scenes: $(call objs,tests/test_scenes.c $(TEST_SUPPORT) $(call stages_upto,$(lastword $(CHAPTERS))) $(COMMON_SRC))
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $^ $(LDLIBS) -lcmocka -o $@

$(BUILD)/tests/test_tools_judge: $(call objs,tests/test_tools_judge.c $(TEST_SUPPORT) tools/judge.c $(COMMON_SRC))
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $^ $(LDLIBS) -lcmocka -o $@

$(BUILD)/tests/test_common_%: $(call objs,tests/test_common_%.c $(TEST_SUPPORT) $(COMMON_SRC))
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $^ $(LDLIBS) -lcmocka -o $@

$(BUILD)/tests/test_fuzz_corpus: $(call objs,tests/test_fuzz_corpus.c $(TEST_SUPPORT) fuzz/support.c \
                                  $(FUZZ_TARGETS:%=fuzz/%.c) $(COMMON_SRC))
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $^ $(LDLIBS) -lcmocka -o $@

# Any build's replay driver: `$(BUILD)/fuzz/replay scene FILE...` (docs/fuzzing.md).
$(BUILD)/fuzz/replay: $(call objs,fuzz/replay.c fuzz/support.c $(FUZZ_TARGETS:%=fuzz/%.c) $(COMMON_SRC))
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

# ---- fuzzing: libFuzzer targets of the readers (docs/fuzzing.md) ------------------
#
# Each target of fuzz/ is built with clang, libFuzzer and the sanitizers (no
# recovery) and run for FUZZ_SECONDS from its seeds in fuzz/corpus/TARGET/;
# what it finds is saved under $(FUZZ_BUILD)/.  stb_image is compiled in, so
# that its decoder is instrumented too.

FUZZ_CC ?= clang
FUZZ_SECONDS ?= 60
FUZZ_BUILD ?= build-fuzz
# What each target links besides fuzz/support.c: only the code it exercises,
# so that its coverage counts the edges it could reach.
FUZZ_SRC_obj := common/mesh.c common/input_file.c
FUZZ_SRC_options := common/options.c
FUZZ_SRC_texture := common/texture_image.c common/input_file.c fuzz/stb_image_impl.c
FUZZ_SRC_scene := common/scene.c common/scene_xml.c $(FUZZ_SRC_obj) $(FUZZ_SRC_texture)
FUZZ_CFLAGS := -std=c11 -Wall -Wextra -Werror -g -O1 -fno-omit-frame-pointer -ffp-contract=off -DRT_LIBFUZZER \
               -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all

deps-fuzz:
	@tools/deps.sh "$(FUZZ_CC)" fuzz

define fuzz_rules
$(FUZZ_BUILD)/fuzz_$1: fuzz/$1.c fuzz/support.c $(FUZZ_SRC_$1) $(wildcard fuzz/*.h common/*.h) | deps-fuzz
	@mkdir -p $$(@D)
	$$(QLINK)$$(FUZZ_CC) $$(CPPFLAGS) $$(FUZZ_CFLAGS) $$(filter %.c,$$^) -lexpat -lm -o $$@
endef
$(foreach t,$(FUZZ_TARGETS),$(eval $(call fuzz_rules,$t)))

ifeq ($(HANDOUT),)
fuzz-build: $(FUZZ_TARGETS:%=$(FUZZ_BUILD)/fuzz_%)

fuzz: fuzz-build
	@tools/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)
else
fuzz fuzz-build:
	@echo "make $@: the fuzz targets (fuzz/) are not in a student's copy" >&2; exit 2
endif

# ---- skeletons: the students' files, generated from the solutions ---------------

SOLUTION_FILES := $(sort $(wildcard solutions/[0-9][0-9]_*/*.c))

# Writes chapters/NN_name/FILE.c from solutions/NN_name/FILE.c by tools/skeleton.awk.
# A student's copy has no solutions/ to write them from: its skeletons are the exercises.
NO_SOLUTIONS = @$(if $(HANDOUT),echo "make $@: this student's copy has no solutions/; its chapters/ hold the exercises" >&2; exit 2)

skeletons:
	$(NO_SOLUTIONS)
	@tools/skeletons.sh write $(SOLUTION_FILES)

check-skeletons:
	$(NO_SOLUTIONS)
	@tools/skeletons.sh check $(SOLUTION_FILES)

# ---- grading --------------------------------------------------------------------
#
# Chapter N is graded with a suite linked with the student's stage files of
# chapter N (SOURCE=chapters) and the reference versions of every other
# chapter's exercise files (solutions/, or in a student's copy the libraries
# in reference/), so an early mistake costs points in its own chapter only.
# tools/grade runs each test alone (`SUITE --only NAME`) with a time limit.
# SOURCE=reference (or SOURCE=solutions where they exist) grades the
# reference instead, and fails unless it gets full marks.  The student's files
# are compiled without -Werror (a warning is shown, it does not cost the
# chapter), and also in the float build (REAL=float), which is reported for
# each test but scores nothing (docs/instructor-guide.md).

SOURCE ?= chapters
TIMEOUT ?= 10
CHAPTER ?=
GRADE_BUILD ?= build-grade$(compiler)
GRADE_JSON ?= $(GRADE_BUILD)/results.json
GRADE_JUNIT ?= $(GRADE_BUILD)/junit.xml
GRADE_FLOAT ?= 1
# GRADE_USER=name runs the tests as that user (the autograder; needs root);
# GRADE_NOTES=file is shown above the results (the autograder's file list).
GRADE_USER ?=
# With GRADE_USER, one grading at a time: each kills every process of that
# user after every test and compiles the student's files as that user, so a
# second grading waits, saying so, for a lock in /run (root's alone), which
# flock(1) holds (-o: no test inherits it).  $(call locked,COMMAND)
grade_lock_file = /run/rt-grade-$(GRADE_USER).lock
locked = $(if $(GRADE_USER),flock -o -n -E 75 $(grade_lock_file) $1; s=$$?; if [ $$s = 75 ]; then \
    echo "make grade: another grading runs as '$(GRADE_USER)': waiting for it to end" >&2; \
    flock -o $(grade_lock_file) $1; else exit $$s; fi,$1)
GRADE_NOTES ?=
# The whole grading's time (seconds) and each test's memory (MB): tools/grade.
GRADE_BUDGET ?= 3600
GRADE_MEMORY ?= 1024
ifeq ($(filter $(SOURCE),chapters solutions reference),)
$(error SOURCE must be chapters, reference or solutions, not '$(SOURCE)')
endif
ifeq ($(SOURCE)$(HANDOUT),solutions1)
$(error this copy has no solutions/: SOURCE=reference grades the compiled reference libraries)
endif

# The chapters to grade: those with a suite, or only CHAPTER (01 or 01_camera_rays).
GRADE_CHAPTERS := $(strip $(foreach t,$(CHAPTER_TESTS),$(if $(or $(if $(CHAPTER),,all),$(filter $(CHAPTER),$(t:test_%=%) $(call num,$(t:test_%=%)))),$(t:test_%=%))))
GRADE_DIR = $(BUILD)/grade-$(SOURCE)
# The stage objects of chapters 1..$1, the student's own for chapter $1 itself.
grade_stages = $(foreach c,$(call upto,$1),$(call stage_objs,$c,$(if $(and $(filter $c,$1),$(filter chapters,$(SOURCE))),1,0)))
# What chapter $1's graded suite links, in words.
REFERENCE_WORDS := $(if $(HANDOUT),the compiled reference libraries reference/double/,solutions/)
# "04_many_shapes: chapters/04_many_shapes/closest_hit.c, with chapters 01 02 03 from the reference (...)"
grade_from_reference = $(strip $(foreach c,$(if $(filter chapters,$(SOURCE)),$(filter-out $1,$(call upto,$1)),$(call upto,$1)),$(if $(EXERCISES_$c),$(call num,$c))))
grade_links = $1: $(if $(filter chapters,$(SOURCE)),$(if $(EXERCISES_$1),$(addprefix chapters/$1/,$(EXERCISES_$1)),no exercise files of its own)$(if $(call grade_from_reference,$1),$(comma) with ))$(if $(call grade_from_reference,$1),chapter$(if $(word 2,$(call grade_from_reference,$1)),s) $(call grade_from_reference,$1) from the reference ($(REFERENCE_WORDS)))

# A graded suite is linked before its student's objects are checked (tools/check-exercise.sh), and
# without -fno-lto the linker would compile, as root, any .gnu.lto_ sections an object holds (a
# top-level asm makes them) with the options they name: -Xassembler --MD=FILE wrote FILE anywhere.
# The link has a compile's limits (tools/compile-as.sh), its time included (120 s, or what is left of
# the grading's budget): an empty section of the object's that the output must hold as zeros (a 6 GiB
# NOBITS .interp) had root's linker hold 6 GiB, twice.
# A graded suite links its chapter's lab only when the suite uses it (chapters 03 and 06): any global
# function of the lab is the student's to call, and chapter 11's fast grid holds the exercise's own
# grid_cell_range ("the same arithmetic and the same answers").
grade_lab_objs = $(if $(shell grep -l '$1/lab/' tests/test_$1.c $(call seeded,$1) 2>/dev/null),$(call lab_objs,$1))
define grade_rules
$(GRADE_DIR)/test_$1: $(call objs,tests/test_$1.c $(TEST_SUPPORT) $(call seeded,$1)) $(call grade_stages,$1) $(call grade_lab_objs,$1) $(call objs,$(COMMON_SRC))
	@mkdir -p $$(@D)
	$$(QLINK)ulimit -v $$$$(($(GRADE_MEMORY) * 1024)) -f $$$$((64 * 1024)) && limit=120 && \
	    if [ -n "$$$${GRADE_DEADLINE:-}" ]; then left=$$$$((GRADE_DEADLINE - $$$$(date +%s))); \
	        [ "$$$$left" -ge "$$$$limit" ] || limit=$$$$left; [ "$$$$limit" -ge 1 ] || limit=1; fi && \
	    timeout -k 5 $$$$limit $$(call link,$$^) -fno-lto -lcmocka -o $$@
endef
$(foreach c,$(CHAPTER_TESTS:test_%=%),$(eval $(call grade_rules,$c)))

$(BUILD)/tools/%: $(BUILD)/obj/tools/%.o
	@mkdir -p $(@D)
	$(QLINK)$(CC) $^ -o $@

grade:
	@$(if $(GRADE_CHAPTERS),,echo "make grade: $(if $(CHAPTER),no chapter '$(CHAPTER)' has a test suite,no chapter has a test suite) (chapters with one: $(or $(CHAPTER_TESTS:test_%=%),none))" >&2; exit 2)
	@$(if $(GRADE_USER),! setpriv --reuid=$(GRADE_USER) --regid="$$(id -g $(GRADE_USER))" --clear-groups -- test -x "$(CURDIR)" || { \
	    echo "make grade: the user $(GRADE_USER) can enter $(CURDIR): a submission's #include could read its files" \
	        "($(if $(HANDOUT),the builds,solutions/ and the builds)); make it root's alone (chmod go-rwx)$(comma) as the autograder's setup.sh does" >&2; exit 2; })
	@$(call locked,$(MAKE) --no-print-directory -s BUILD=$(GRADE_BUILD) STUDENT=0 REAL=double SANITIZE=0 grade-run)

# Run by `grade` in the grading build.  A chapter whose reference suite does
# not build is not graded; a student's suite that does not compile fails that
# chapter's tests only.  The student's objects are always rebuilt: a file
# copied in with an old time stamp is not taken for up to date.
FLOAT_GRADE_DIR = $(BUILD)-float/grade-$(SOURCE)
grade-run: $(BUILD)/tools/grade
	@mkdir -p $(GRADE_DIR) $(FLOAT_GRADE_DIR); set -- ; missing=""; notes=$(GRADE_DIR)/notes.txt; \
	export GRADE_DEADLINE=$$(( $$(date +%s) + $$(printf '%.0f' '$(GRADE_BUDGET)') )) GRADE_MEMORY=$(GRADE_MEMORY); \
	{ $(if $(GRADE_NOTES),cat $(GRADE_NOTES);) true; } >$$notes; \
	for c in $(GRADE_CHAPTERS); do \
	    if ! $(MAKE) --no-print-directory -s $(BUILD)/tests/test_$$c >$(GRADE_DIR)/reference_$$c.log 2>&1; then \
	        echo "$$c: not graded, its reference suite does not build (see $(GRADE_DIR)/reference_$$c.log)"; \
	        missing="$$missing $$c"; continue; \
	    fi; \
	    case $$c in $(foreach c,$(GRADE_CHAPTERS),$c$(rparen) ex="$(EXERCISES_$c)";;) esac; \
	    rm -f $(GRADE_DIR)/test_$$c $(BUILD)/obj/chapters/$$c/*.o; \
	    $(MAKE) --no-print-directory -s WERROR= COMPILE_AS=$(GRADE_USER) $(GRADE_DIR)/test_$$c >$(GRADE_DIR)/test_$$c.log 2>&1 || { \
	        echo "$$c: the files of $(SOURCE)/$$c/ do not compile:"; \
	        tail -n 20 $(GRADE_DIR)/test_$$c.log | $(BUILD)/tools/grade --clean; }; \
	    $(call grade_check,$(GRADE_DIR)/test_$$c,$(if $(HANDOUT),reference/double/lib$$c.a,$(BUILD)/obj/solutions/$$c),$(BUILD),print); \
	    float=- float_log=- float_ref=-; \
	    if [ "$(GRADE_FLOAT)" = 1 ]; then \
	        float=$(FLOAT_GRADE_DIR)/test_$$c float_log=$(FLOAT_GRADE_DIR)/test_$$c.log float_ref=$(BUILD)-float/tests/test_$$c; \
	        $(MAKE) --no-print-directory -s BUILD=$(BUILD)-float REAL=float $$float_ref >$(FLOAT_GRADE_DIR)/reference_$$c.log 2>&1 || { \
	            echo "$$c: not graded, its float reference suite does not build (see $(FLOAT_GRADE_DIR)/reference_$$c.log)"; \
	            missing="$$missing $$c"; continue; }; \
	        rm -f $$float $(BUILD)-float/obj/chapters/$$c/*.o; \
	        $(MAKE) --no-print-directory -s BUILD=$(BUILD)-float REAL=float WERROR= COMPILE_AS=$(GRADE_USER) $$float \
	            >$$float_log 2>&1 || true; \
	        $(call grade_check,$$float,$(if $(HANDOUT),reference/float/lib$$c.a,$(BUILD)-float/obj/solutions/$$c),$(BUILD)-float,); \
	    fi; \
	    set -- "$$@" $$c $(GRADE_DIR)/test_$$c $(BUILD)/tests/test_$$c $(GRADE_DIR)/test_$$c.log $$float $$float_log $$float_ref; \
	done; \
	$(foreach c,$(GRADE_CHAPTERS),echo "$(call grade_links,$c)" >>$$notes;) \
	echo "grading $(SOURCE)/ ($(TIMEOUT) s per test$(if $(filter 1,$(GRADE_FLOAT)),; the float build is reported, not scored))"; \
	$(BUILD)/tools/grade --clean <$$notes; \
	left=$$(( GRADE_DEADLINE - $$(date +%s) )); [ "$$left" -ge 1 ] || left=1; \
	$(BUILD)/tools/grade --timeout $(TIMEOUT) --budget $$left --memory $(GRADE_MEMORY) \
	    --json $(GRADE_JSON) --junit $(GRADE_JUNIT) --notes $$notes \
	    $(if $(GRADE_USER),--user $(GRADE_USER)) \
	    $(if $(filter-out chapters,$(SOURCE)),--require-full) "$$@" || exit 1; \
	echo "wrote $(GRADE_JSON) (Gradescope) and $(GRADE_JUNIT) (JUnit)"; \
	if [ -n "$$missing" ]; then echo "not graded:$$missing"; exit 1; fi

rparen := )
# $(call grade_check,SUITE,REFERENCE,BUILD,print): the student's objects of
# chapter $$c (files $$ex) checked before their suite is run
# (tools/check-exercise.sh): a refusal removes SUITE and goes into its log
# (and, with print, on the terminal); a match of the reference's code is
# flagged on the terminal (with print) only, for the instructor.  The check
# runs as root on the student's text: it has what is left of the grading's
# budget, as a compile does, so that no slow path of it outlasts the budget.
grade_check = $(if $(filter chapters,$(SOURCE)),if [ -x $1 ]; then \
	    left=$$(( GRADE_DEADLINE - $$(date +%s) )); [ "$$left" -ge 1 ] || left=1; \
	    CC="$(CC)" CPPFLAGS="$(CPPFLAGS) $(filter-out -Werror,$(CFLAGS)) $(if $(findstring float,$3),-DRT_REAL_FLOAT)" \
	        COMPILE_AS=$(GRADE_USER) \
	        timeout -k 5 $$left tools/check-exercise.sh $2 chapters/$$c $3/obj/chapters/$$c $$ex >$1.check || { \
	        rc=$$?; [ $$rc -ne 124 ] && [ $$rc -ne 137 ] || \
	            echo "$$c: refused: the check of its files took longer than the grading's budget" >>$1.check; \
	        rm -f $1; grep refused $1.check >>$1.log; }; \
	    $(if $4,$(BUILD)/tools/grade --clean <$1.check;) fi,true)

# The grader: tools/grade.c, the verdict (judge.c), the scratch folders (scratch.c), the tests' seal (seal.c).
$(BUILD)/tools/grade: $(addprefix $(BUILD)/obj/tools/,grade.o judge.o scratch.o seal.o)
	@mkdir -p $(@D)
	$(QLINK)$(CC) $^ -lm -o $@

# ---- the student's copy and the autograder ---------------------------------------
#
# `make handout DEST=dir` writes the repository a student receives: no
# solutions/, and the reference of every chapter's exercise files as compiled
# libraries, reference/double/ and reference/float/ (tools/handout.sh).
# `make autograder` zips such a copy with Gradescope's scripts
# (tools/autograder.sh).  Neither holds a line of solution source; both check it.
# The handout also ships the book (book/, tools/book/), built in the copy from
# its own files: the exercises appear in it as the skeletons.

DEST ?=
REFERENCE_CHAPTERS = $(foreach c,$(CHAPTERS),$(if $(EXERCISES_$c),$c))
reference-libs: $(foreach c,$(REFERENCE_CHAPTERS),$(BUILD)/reference/lib$c.a)

# The libraries are built without debugging information, in builds of their own.
handout-libs:
	@$(if $(HANDOUT),echo "make handout: this is already a student's copy (no solutions/)" >&2; exit 2)
	@$(MAKE) --no-print-directory -s STUDENT=0 SANITIZE=0 REAL=double OPT=-O2 BUILD=build-handout reference-libs
	@$(MAKE) --no-print-directory -s STUDENT=0 SANITIZE=0 REAL=float OPT=-O2 BUILD=build-handout-float reference-libs

handout: handout-libs
	@$(if $(DEST),,echo "make handout: say where, DEST=dir" >&2; exit 2)
	@tools/handout.sh "$(DEST)" build-handout/reference build-handout-float/reference
	@tools/deps.sh "$(CC)" book && (cd "$(DEST)" && tools/book/build.sh book) || \
	    { rm -rf "$(DEST)"; echo "handout: the book of the copy could not be built; $(DEST) removed" >&2; exit 1; }

# A Gradescope autograder: a student's copy, setup.sh and run_autograder in one zip.
AUTOGRADER ?= $(GRADE_BUILD)/autograder$(if $(CHAPTER),-$(CHAPTER)).zip
autograder: handout-libs
	@$(if $(CHAPTER),$(if $(GRADE_CHAPTERS),,echo "make autograder: no chapter '$(CHAPTER)' has a test suite" >&2; exit 2))
	@tools/autograder.sh $(AUTOGRADER) "$(CHAPTER)" "$(TIMEOUT)" build-handout/reference build-handout-float/reference \
	    $(if $(filter command line environment,$(origin GRADE_BUDGET)),$(GRADE_BUDGET),1200)

# ---- figures: the lecture figures of each chapter, rendered by its solution --------

FIGURE_LISTS := $(sort $(wildcard chapters/$(if $(CHAPTER),$(CHAPTER:%_=%)*,[0-9][0-9]_*)/figures.txt))
# The builds the figures come from: BUILD when given, else the plain double
# build (FIG_BUILD) and its float twin (FIG_BUILD-float).
FIG_BUILD ?= $(if $(filter command line environment,$(origin BUILD)),$(BUILD),build$(compiler))
# "double/01_camera_rays" for each renderer a figure needs.
# A gnuplot line (a plot) may run both builds of its chapter.
FIG_NEEDS := $(if $(FIGURE_LISTS),$(shell awk 'NF >= 2 && $$1 !~ /^\#/ { n = split(FILENAME, p, "/"); if ($$2 == "gnuplot") { print "double/" p[n - 1]; print "float/" p[n - 1]; print "double-lab/" p[n - 1]; print "float-lab/" p[n - 1] } else print $$2 "/" p[n - 1] }' $(FIGURE_LISTS) | sort -u))
FIG_DOUBLE := $(patsubst double/%,$(FIG_BUILD)/%/render,$(filter double/%,$(FIG_NEEDS)))
FIG_FLOAT := $(patsubst float/%,$(FIG_BUILD)-float/%/render,$(filter float/%,$(FIG_NEEDS)))
# A figure of a lab names its build double-lab or float-lab.
# (A plot may run both; a chapter without a lab has none to build.)
FIG_DOUBLE += $(patsubst double-lab/%,$(FIG_BUILD)/%/lab,$(filter $(LAB_CHAPTERS:%=double-lab/%),$(FIG_NEEDS)))
FIG_FLOAT += $(patsubst float-lab/%,$(FIG_BUILD)-float/%/lab,$(filter $(LAB_CHAPTERS:%=float-lab/%),$(FIG_NEEDS)))

# Puts labelled panels side by side (the `panels` lines of figures.txt).
$(BUILD)/tools/panels: $(BUILD)/obj/tools/panels.o
	@mkdir -p $(@D)
	$(QLINK)$(CC) $^ -lstb -lm -o $@

# chapters/10_interpolation/scenes/globe.png is globe_texture's map (sphere_mesh.h) as a file.
$(BUILD)/tools/globe-png: $(call objs,tools/globe-png.c chapters/10_interpolation/scenes/sphere_mesh.c $(COMMON_SRC))
	@mkdir -p $(@D)
	$(QLINK)$(call link,$^) -lstb -o $@

globe-texture: $(BUILD)/tools/globe-png
	$(BUILD)/tools/globe-png chapters/10_interpolation/scenes/globe.png

# chapters/10_interpolation/scenes/closeup.png, the texture of the close-up figure (10_filters.png).
$(BUILD)/tools/closeup-png: $(BUILD)/obj/tools/closeup-png.o
	@mkdir -p $(@D)
	$(QLINK)$(CC) $^ -lstb -lm -o $@

.PHONY: closeup-texture
closeup-texture: $(BUILD)/tools/closeup-png
	$(BUILD)/tools/closeup-png chapters/10_interpolation/scenes/closeup.png

figure-renderers:
	@tools/deps.sh "$(CC)" figures
	@$(MAKE) --no-print-directory -s STUDENT=0 SANITIZE=0 REAL=double BUILD=$(FIG_BUILD) $(FIG_BUILD)/tools/panels
	@$(if $(FIG_DOUBLE),$(MAKE) --no-print-directory -s STUDENT=0 SANITIZE=0 REAL=double BUILD=$(FIG_BUILD) $(FIG_DOUBLE))
	@$(if $(FIG_FLOAT),$(MAKE) --no-print-directory -s STUDENT=0 SANITIZE=0 REAL=float BUILD=$(FIG_BUILD)-float $(FIG_FLOAT))

figures: figure-renderers
	@tools/figures.sh render $(FIG_BUILD) $(FIGURE_LISTS)

check-figures: figure-renderers
	@tools/figures.sh check $(FIG_BUILD) $(FIGURE_LISTS)

# ---- snippets: the code shown in the texts, taken from the source ----------------

SNIPPET_TEXTS := $(sort $(wildcard chapters/[0-9][0-9]_*/README.md chapters/[0-9][0-9]_*/lab/*.md docs/*.md))

snippets:
	$(NO_SOLUTIONS)
	@tools/snippets.sh fill $(SNIPPET_TEXTS)

# Every relative link of the texts resolves; nothing names a file beside the repository.
check-links:
	@tools/check-links.sh

check-snippets:
	@tools/snippets.sh check $(SNIPPET_TEXTS)

# The example outputs of the texts (<!-- output: COMMAND -->), from the renderers and labs of BUILD.
outputs: renderers
	@tools/outputs.sh fill $(BUILD) $(SNIPPET_TEXTS)

check-outputs: renderers
	@tools/outputs.sh check $(BUILD) $(SNIPPET_TEXTS)

# What a student reads and writes, per chapter, against the budgets (tools/lesson-lines.sh).
check-lessons:
	@tools/lesson-lines.sh --check

# Every graded test checks inputs drawn at grading time (tests/seeded/).
check-seeded: $(addprefix $(BUILD)/tests/,$(CHAPTER_TESTS))
	@tools/check-seeded.sh $^

# Chapter 11 renders the images of chapter 10, byte for byte.
check-grid-images: $(BUILD)/10_interpolation/render $(BUILD)/11_grid/render $(BUILD)/11_grid/lab
	@tools/check-grid-images.sh $(BUILD)

# Text, skeletons and figures agree with their sources; the grid changes no
# pixel (in the repository; a student's copy has no solutions/ to compare
# them with).
check: $(if $(HANDOUT),,check-skeletons check-snippets check-outputs check-lessons check-figures check-links check-grid-images check-seeded)
	@$(if $(HANDOUT),echo "make check: nothing to check in a student's copy (it compares texts, skeletons and figures with solutions/)")

# ---- tests ----------------------------------------------------------------------

# One build's suites: build them all, run them all, and count.
test-suites: $(TEST_BINS)
	@V=$(V) tools/run-tests.sh $(BUILD)/test-results.txt $(TEST_BINS)

# Every renderer of this build over the scenes at the extremes, the chapters'
# own and the Cornell corpus's: no NaN or infinite sample, no crash, and (in
# the sanitizer build) no undefined behaviour.
test-extremes: renderers
	@tools/extremes.sh $(BUILD)

# The build's own behaviour: what make prints, where the images go, which
# packages it needs, what a student's copy says of itself (tests/make.sh).
.PHONY: test-make
test-make: $(foreach c,$(filter 04_% 07_% 11_%,$(CHAPTERS)),$(BUILD)/$c/render)
	@CC="$(CC)" BUILD="$(BUILD)" tests/make.sh

# The double build, the float build and the sanitizer build (with the
# renders at the extremes and the fuzz corpus replay), then the build's own
# checks and the checks that text, skeletons and figures match their sources,
# the book in Chromium, then (as root) the hostile submissions against the
# autograder.
test:
	@rm -f build*/test-results.txt
	$(Q)$(MAKE) --no-print-directory test-suites
	$(Q)$(MAKE) --no-print-directory REAL=float BUILD=$(BUILD)-float test-suites
	$(Q)$(MAKE) --no-print-directory SANITIZE=1 OPT="-O1 -g" BUILD=$(BUILD)-asan test-suites
	$(Q)$(MAKE) --no-print-directory SANITIZE=1 OPT="-O1 -g" BUILD=$(BUILD)-asan test-extremes
	@tools/sum-results.sh $(BUILD) $(BUILD)-float $(BUILD)-asan
	$(Q)$(MAKE) --no-print-directory test-make
	$(Q)$(MAKE) --no-print-directory check
	$(Q)$(MAKE) --no-print-directory test-book
	$(Q)$(MAKE) --no-print-directory test-hostile

# ---- bench: the speed/accuracy measurements of docs/measurements.md ----------------
#
# Not part of `make test`: timings never are.  Builds the double and float
# renderers and the bench's tools, then bench/bench.sh measures and writes
# docs/measurements.md and docs/figures/bench_*.png (BENCH_REPS=5 rounds).

BENCH_BUILD ?= build$(compiler)
BENCH_TOOLS := $(addprefix $(BUILD)/bench-tools/,imgcmp tessellate checker scene2pov)

$(BUILD)/bench-tools/scene2pov: $(call objs,bench/scene2pov.c $(COMMON_SRC))
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

$(BUILD)/bench-tools/%: $(BUILD)/obj/bench/%.o
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $^ $(LDLIBS) -o $@

.PHONY: bench bench-tools
bench-tools: $(BENCH_TOOLS)

bench:
	@$(if $(HANDOUT),echo "make bench: the benchmarks (bench/) are not in a student's copy; docs/measurements.md has their results" >&2; exit 2)
	@tools/deps.sh "$(CC)" bench
	@$(MAKE) --no-print-directory -s STUDENT=0 SANITIZE=0 REAL=double BUILD=$(BENCH_BUILD) renderers bench-tools \
	    $(BENCH_BUILD)/tools/panels
	@$(MAKE) --no-print-directory -s STUDENT=0 SANITIZE=0 REAL=float BUILD=$(BENCH_BUILD)-float renderers
	@CC="$(CC)" bench/bench.sh $(BENCH_BUILD) $(BENCH_BUILD)-float $(BENCH_BUILD)/bench-tools

# ---- help -----------------------------------------------------------------------

# help: a student's copy lists only what it has (no solutions/, bench/, fuzz/).
REPO_ONLY = $(if $(HANDOUT),@: ,@)
COPY_ONLY = $(if $(HANDOUT),@,@: )
help:
	@echo "make                 build every chapter and render its built-in scene into $(OUT)/ (each build variant"
	@echo "                     has its own image folder, as it has its own build folder: REAL=float, out$(compiler)-float$(if $(filter 1,$(STUDENT)),-student)/)"
	$(REPO_ONLY)echo "make STUDENT=1       the same from the student's files in chapters/ (into build-student/)"
	$(COPY_ONLY)echo "                     (here from your files in chapters/, into build-student/ and out-student/)"
	$(COPY_ONLY)echo "make STUDENT=0       the reference renderers (from reference/) into build/, their images into out/"
	$(REPO_ONLY)echo "make test            all suites: double, float (REAL=float) and sanitizer builds, make check, test-hostile"
	$(COPY_ONLY)echo "make test            all suites on all your files: double, float (REAL=float) and sanitizer builds"
	@echo "make test-make       the build's own behaviour: output, image folders, packages, the student's copy"
	@echo "make test-extremes   every renderer over tests/extremes/ and the other scenes, failing on NaN"
	@echo "make test-hostile    hostile submissions against chapter 05's autograder under a fake root (root only)"
	@echo "make renderers       build every chapter's renderer into $(BUILD)/NN_name/render"
	@echo "make tests           build the test suites of this build"
	@echo "make test-suites     run the suites of this build only"
	$(REPO_ONLY)echo "make grade           grade the student's files: chapter N with the solutions of the others,"
	$(COPY_ONLY)echo "make grade           grade your files: chapter N with the reference of the others,"
	@echo "                     each test alone with a time limit; a score table, $(GRADE_JSON)"
	@echo "                     (Gradescope) and $(GRADE_JUNIT) (JUnit)"
	$(REPO_ONLY)echo "  CHAPTER=01         grade one chapter;  SOURCE=solutions  grade the solutions (must be full marks)"
	$(COPY_ONLY)echo "  CHAPTER=01         grade one chapter;  SOURCE=reference  grade the reference (full marks)"
	@echo "  TIMEOUT=10         seconds per test"
	@echo "  GRADE_FLOAT=0      without the float build (reported, not scored)"
	$(REPO_ONLY)echo "make handout DEST=d  the student's copy: no solutions/, compiled reference libraries in reference/"
	$(REPO_ONLY)echo "make autograder      a Gradescope autograder zip (CHAPTER=01: one chapter) into $(GRADE_BUILD)/,"
	$(REPO_ONLY)echo "                     a student's copy plus setup.sh and run_autograder (docs/instructor-guide.md)"
	$(REPO_ONLY)echo "make skeletons       write chapters/NN_name/*.c from solutions/ by tools/skeleton.awk"
	@echo "make figures         render the figures of chapters/*/figures.txt into docs/figures/"
	$(REPO_ONLY)echo "make globe-texture   write chapter 10's scenes/globe.png from globe_texture (sphere_mesh.c)"
	$(REPO_ONLY)echo "make closeup-texture write chapter 10's scenes/closeup.png (tools/closeup-png.c, for 10_filters.png)"
	$(REPO_ONLY)echo "make snippets        fill the code blocks of the READMEs from the source"
	$(REPO_ONLY)echo "make check           check-skeletons, -snippets, -outputs, -lessons (docs/design.md), -figures, -links,"
	$(REPO_ONLY)echo "                     -grid-images (chapter 11's images byte for byte the linear scan's), -seeded"
	$(REPO_ONLY)echo "                     (every graded test checks inputs drawn at grading time): fail naming what is stale"
	$(REPO_ONLY)echo "make bench           measure every knob's cost and benefit, POV-Ray, growth, threads: writes"
	$(REPO_ONLY)echo "                     docs/measurements.md and docs/figures/bench_*.png (not part of make test)"
	$(REPO_ONLY)echo "make bench-grid      chapter 11's grid against the linear scan and Embree 3 (installs libembree-dev, glmark2-data)"
	$(REPO_ONLY)echo "make fuzz            build the libFuzzer targets (clang) and fuzz each for FUZZ_SECONDS (60) seconds;"
	$(REPO_ONLY)echo "                     findings go to $(FUZZ_BUILD)/ (docs/fuzzing.md)"
	@echo "make book            the course as a static site in build/book/ (open index.html): pages, equations, listings"
	@echo "make check-book      every page of the book in headless Chromium: errors, images, equations, links, phone width"
	@echo "make clean           remove build*/ and out*/"
	@echo "variables: REAL=float  STUDENT=1 (build the skeletons in chapters/)  SANITIZE=1  CC=clang  BUILD=dir"
	@echo "           V=1 (every command and each suite's whole output; by default one line each, logs in BUILD/logs/)"
	@echo "           REFERENCE=\"01 02\" (with STUDENT=1: these chapters from the reference)"
	@echo "chapters: $(CHAPTERS)"

clean:
	rm -rf build build-* out out-*

include tools/book/book.mk

# The grid's benchmark against Embree (make bench-grid); a student's copy has no bench/.
ifeq ($(HANDOUT),)
include bench/grid/grid.mk
else
.PHONY: bench-grid
bench-grid:
	@echo "make bench-grid: the benchmarks (bench/) are not in a student's copy; chapter 11's README has its results" >&2; exit 2
endif

# Hostile submissions against the autograder (make test-hostile; root only);
# a student's copy has no tests/hostile/.
ifneq ($(wildcard tests/hostile/hostile.mk),)
include tests/hostile/hostile.mk
else
.PHONY: test-hostile
test-hostile:
	@echo "hostile submissions: not in this copy (tests/hostile/ is the repository's)"
endif

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
