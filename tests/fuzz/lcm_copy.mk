# lcm_copy.mk - the fuzz target's object includes the lcm-gen headers
# (mk/lcm.mk generates them; tests/fuzz/*.mk are read before mk/lcm.mk, so
# the stamp is named literally).
$(BUILD)/obj/tests/fuzz/fuzz_lcm_copy.o: $(BUILD)/gen/lcm/.stamp
