# tests/test_tracker_noclutter.mk - test_tracker_noclutter runs the tracker
# built with -DTRK_WITH_CLUTTER_TESTS=0 (config.h): tracker.c and
# track_tests.c, the only library files whose layout depends on the knob, are
# compiled again in that configuration and linked ahead of libtrk.a (which
# then contributes everything else); the test source defines the knob itself.
NOCLUTTER_OBJS := $(BUILD)/obj/noclutter/src/tracker.o $(BUILD)/obj/noclutter/src/track_tests.o
$(BUILD)/obj/noclutter/src/%.o: src/%.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$< (TRK_WITH_CLUTTER_TESTS=0))
	$(Q)$(CC) $(CFLAGS_ALL) $(LIBWARN) -DTRK_WITH_CLUTTER_TESTS=0 -Isrc -c $< -o $@
$(BUILD)/tests/test_tracker_noclutter: $(NOCLUTTER_OBJS)
TEST_EXTRA_OBJS_test_tracker_noclutter := $(NOCLUTTER_OBJS)
