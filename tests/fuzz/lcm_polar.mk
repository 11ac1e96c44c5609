# lcm_polar.mk - the polar fuzz target's object includes the lcm-gen headers
# (mk/lcm.mk generates them; tests/fuzz/*.mk are read before mk/lcm.mk, so
# the stamp is named literally).
$(BUILD)/obj/tests/fuzz/fuzz_lcm_polar.o: $(BUILD)/gen/lcm/.stamp
