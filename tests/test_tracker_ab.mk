# tests/test_tracker_ab.mk - test_tracker_ab runs the tracker built with
# -DTRK_WITH_ALPHA_BETA=1 (config.h): the scan (tracker.c) and the parameter
# check (tracker_params.c), the library files whose code depends on the knob,
# are compiled again in that configuration and linked ahead of libtrk.a,
# which contributes the rest (the knob changes no layout); the test source
# sets the knob itself.
AB_TEST_OBJS := $(addprefix $(BUILD)/obj/ab/src/,tracker.o tracker_params.o)
$(BUILD)/obj/ab/src/%.o: src/%.c $(wildcard src/*.h include/trk/*.h) $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,CC,$< (TRK_WITH_ALPHA_BETA=1))
	$(Q)$(CC) $(CFLAGS_ALL) $(LIBWARN) -UTRK_WITH_ALPHA_BETA -DTRK_WITH_ALPHA_BETA=1 -Isrc -c $< -o $@
$(BUILD)/tests/test_tracker_ab: $(AB_TEST_OBJS)
TEST_EXTRA_OBJS_test_tracker_ab := $(AB_TEST_OBJS)
