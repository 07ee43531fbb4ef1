# Hostile submissions against chapter 05's Gradescope autograder, under a
# fake root (tools/hostile.sh; part of `make test` as root).  The recorder is
# chapter 05's suite with every call of lambert written down: the "table"
# attack's data.

.PHONY: test-hostile

$(BUILD)/hostile/record_05_lambert: $(call objs,tests/test_05_lambert.c $(TEST_SUPPORT) $(call seeded,05_lambert) \
                                      tests/hostile/record_lambert.c) \
                                    $(call stages_upto,05_lambert) $(call objs,$(COMMON_SRC))
	@mkdir -p $(@D)
	$(call link,$^) -Wl,--wrap=lambert -lcmocka -o $@

test-hostile:
	@tools/hostile.sh
