# The one entry point of the teaching ray tracer.  `make help` lists the targets.
#
# Chapters are found by directory: chapters/NN_name/.  Chapter N's renderer
# links common/ and the stage files (every .c but render.c) of chapters 1..N.
# A stage file that has exercises exists twice: the complete version in
# solutions/NN_name/ and the student's skeleton in chapters/NN_name/.  By
# default every build takes the solutions; STUDENT=1 takes the skeletons.

.DEFAULT_GOAL := all
SHELL := /bin/bash
.DELETE_ON_ERROR:
.SECONDARY:
.SUFFIXES:

CC ?= cc
REAL ?= double
STUDENT ?= 0
SANITIZE ?= 0
OPT ?= -O2 -g

ifeq ($(filter $(REAL),double float),)
$(error REAL must be double or float, not '$(REAL)')
endif

compiler := $(if $(findstring clang,$(CC)),-clang)
variant := $(compiler)$(if $(filter float,$(REAL)),-float)$(if $(filter 1,$(SANITIZE)),-asan)$(if $(filter 1,$(STUDENT)),-student)
BUILD ?= build$(variant)

CPPFLAGS := -D_POSIX_C_SOURCE=200809L -I common -I chapters -I tests -I /usr/include/stb \
            $(if $(filter float,$(REAL)),-DRT_REAL_FLOAT)
SANITIZERS := -fsanitize=address -fsanitize=undefined
CFLAGS := -std=c11 -Wall -Wextra -Wpedantic -Werror -ffp-contract=off -fopenmp $(OPT) -MMD -MP \
          $(if $(filter 1,$(SANITIZE)),$(SANITIZERS) -fno-sanitize-recover=all -fno-omit-frame-pointer)
LDFLAGS := -fopenmp $(if $(filter 1,$(SANITIZE)),$(SANITIZERS))
LDLIBS := -lstb -lexpat -lm

CHAPTERS := $(sort $(notdir $(patsubst %/,%,$(wildcard chapters/[0-9][0-9]_*/))))
COMMON_SRC := $(sort $(wildcard common/*.c))

# $(call num,01_camera_rays) -> 01
num = $(firstword $(subst _, ,$1))
# The chapters up to and including $1.
upto = $(foreach c,$(CHAPTERS),$(if $(filter $(call num,$c),$(firstword $(sort $(call num,$c) $(call num,$1)))),$c))
# Source of stage file $3 of chapter $1: the solution unless $2 is 1 (student).
pick = $(if $(and $(filter-out 1,$2),$(wildcard solutions/$1/$(notdir $3))),solutions/$1/$(notdir $3),$3)
# The stage files of chapter $1, from the student's files when $2 is 1.
stage_src = $(foreach f,$(sort $(filter-out %/render.c,$(wildcard chapters/$1/*.c))),$(call pick,$1,$2,$f))
# The stage files of chapters 1..$1.
stages_upto = $(foreach c,$(call upto,$1),$(call stage_src,$c,$(STUDENT)))
objs = $(patsubst %.c,$(BUILD)/obj/%.o,$1)

TEST_SUPPORT := tests/suite.c
# Suites of common/ link common/ only; a chapter's suite links its stages.
COMMON_TESTS := $(sort $(basename $(notdir $(wildcard tests/test_common_*.c))))
CHAPTER_TESTS := $(foreach c,$(CHAPTERS),$(if $(wildcard tests/test_$c.c),test_$c))
ALL_TESTS := $(COMMON_TESTS) $(CHAPTER_TESTS)

RENDERERS := $(foreach c,$(CHAPTERS),$(BUILD)/$c/render)
TEST_BINS := $(addprefix $(BUILD)/tests/,$(ALL_TESTS))
IMAGES := $(foreach c,$(CHAPTERS),out/$c.png)

.PHONY: all renderers tests test test-suites deps help clean
all: renderers $(if $(filter 1,$(SANITIZE)),,$(IMAGES))
renderers: $(RENDERERS)
tests: $(TEST_BINS)

# ---- compiling and linking ----------------------------------------------------

deps:
	@tools/deps.sh "$(CC)"

$(BUILD)/obj/%.o: %.c | deps
	@mkdir -p $(@D)
	$(CC) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

define chapter_rules
$(BUILD)/$1/render: $(call objs,chapters/$1/render.c $(call stages_upto,$1) $(COMMON_SRC))
	@mkdir -p $$(@D)
	$$(CC) $$(LDFLAGS) $$^ $$(LDLIBS) -o $$@

out/$1.png: $(BUILD)/$1/render
	@mkdir -p out
	$(BUILD)/$1/render -o $$@

$(BUILD)/tests/test_$1: $(call objs,tests/test_$1.c $(TEST_SUPPORT) $(call stages_upto,$1) $(COMMON_SRC))
	@mkdir -p $$(@D)
	$$(CC) $$(LDFLAGS) $$^ $$(LDLIBS) -lcmocka -o $$@
endef
$(foreach c,$(CHAPTERS),$(eval $(call chapter_rules,$c)))

$(BUILD)/tests/test_common_%: $(call objs,tests/test_common_%.c $(TEST_SUPPORT) $(COMMON_SRC))
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) $^ $(LDLIBS) -lcmocka -o $@

# ---- tests ----------------------------------------------------------------------

# One build's suites: build them all, run them all, and count.
test-suites: $(TEST_BINS)
	@tools/run-tests.sh $(BUILD)/test-results.txt $(TEST_BINS)

# The double build, the float build and the sanitizer build, then the checks
# that text, skeletons and figures match their sources.
test:
	@rm -f build*/test-results.txt
	$(MAKE) --no-print-directory test-suites
	$(MAKE) --no-print-directory REAL=float test-suites
	$(MAKE) --no-print-directory SANITIZE=1 OPT="-O1 -g" test-suites
	@tools/sum-results.sh $(BUILD) $(BUILD)-float $(BUILD)-asan

# ---- help -----------------------------------------------------------------------

help:
	@echo "make                 build every chapter and render its built-in scene into out/"
	@echo "make test            all suites: double, float (REAL=float) and sanitizer builds"
	@echo "make renderers       build every chapter's renderer into $(BUILD)/NN_name/render"
	@echo "make tests           build the test suites of this build"
	@echo "make test-suites     run the suites of this build only"
	@echo "make clean           remove build*/ and out/"
	@echo "variables: REAL=float  STUDENT=1 (build the skeletons in chapters/)  SANITIZE=1  CC=clang"
	@echo "chapters: $(CHAPTERS)"

clean:
	rm -rf build build-* out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
