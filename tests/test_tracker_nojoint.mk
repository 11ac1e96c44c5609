# tests/test_tracker_nojoint.mk - test_tracker_nojoint runs the tracker built
# with -DTRK_WITH_JOINT=0 (config.h): tracker.c and tracker_params.c, the
# library files whose code or layout depends on the knob, are compiled again
# in that configuration and linked ahead of libtrk.a (which then contributes
# everything else); the test source defines the knob itself.
NOJOINT_OBJS := $(BUILD)/obj/nojoint/src/tracker.o $(BUILD)/obj/nojoint/src/tracker_params.o
$(BUILD)/obj/nojoint/src/%.o: src/%.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$< (TRK_WITH_JOINT=0))
	$(Q)$(CC) $(CFLAGS_ALL) $(LIBWARN) -DTRK_WITH_JOINT=0 -Isrc -c $< -o $@
$(BUILD)/tests/test_tracker_nojoint: $(NOJOINT_OBJS)
TEST_EXTRA_OBJS_test_tracker_nojoint := $(NOJOINT_OBJS)
