# The explanation of a pixel (--explain, common/explain.h) checked against the
# image by every renderer of the build: tests/test_explain.c runs them.
ALL_TESTS += test_explain
$(BUILD)/tests/test_explain: $(call objs,tests/test_explain.c $(TEST_SUPPORT) $(COMMON_SRC)) | $(RENDERERS)
	@mkdir -p $(@D)
	$(QLINK)$(CC) $(LDFLAGS) $(filter %.o,$^) $(LDLIBS) -lcmocka -o $@
