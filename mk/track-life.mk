# mk/track-life.mk - the track-life tools as documented (a step of `make
# test`): trk-sim operating-point, trk-sim hyca and trk-sim fading, their CSV invariants
# checked by tests/track_life.sh.
.PHONY: track-life
TEST_EXTRA += track-life
TEST_EXTRA_DEPS_track-life := $(BUILD)/bin/trk-sim
track-life: $(TEST_EXTRA_DEPS_track-life)
	@sh tests/track_life.sh $(BUILD)/bin/trk-sim
