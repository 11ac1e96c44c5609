# test_layout.mk - test_layout links the shared library's self-description
# (src/shared/layout.c, not in libtrk.a) beside the static libraries.
TEST_EXTRA_OBJS_test_layout := $(BUILD)/obj/src/shared/layout.o
$(BUILD)/tests/test_layout: $(BUILD)/obj/src/shared/layout.o
