# tests/test_tracker_imm.mk - test_tracker_imm runs the tracker built with
# -DTRK_WITH_IMM=1 (config.h) in every configuration of the matrix: the
# library files whose code or layout depends on the knob (the tracker, its
# parameters, the track tests that read struct trk_tracker, and status.c's
# trk_with_imm() for the ABI check) are compiled again in that
# configuration and linked ahead of libtrk.a, which contributes the rest;
# the test source sets the knob itself.
IMM_TEST_OBJS := $(addprefix $(BUILD)/obj/imm/src/,tracker.o tracker_params.o track_tests.o status.o)
$(BUILD)/obj/imm/src/%.o: src/%.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$< (TRK_WITH_IMM=1))
	$(Q)$(CC) $(CFLAGS_ALL) $(LIBWARN) -UTRK_WITH_IMM -DTRK_WITH_IMM=1 -Isrc -c $< -o $@
$(BUILD)/tests/test_tracker_imm: $(IMM_TEST_OBJS)
TEST_EXTRA_OBJS_test_tracker_imm := $(IMM_TEST_OBJS)
