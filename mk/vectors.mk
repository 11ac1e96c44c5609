# mk/vectors.mk - `trk-vectors --emit` writes only what the library computed
# (a step of `make test`): a case of a kind this build does not implement,
# and a case it cannot answer (e.g. a 4-model IMM case in a build with
# TRK_MAX_MODELS = 3: tests/vectors/imm.vec is checked too), come back with
# their in and tol lines and a "# not computed" comment per output, and no
# out line copied from the expected values.
.PHONY: vectors-emit
TEST_EXTRA += vectors-emit
TEST_EXTRA_DEPS_vectors-emit := $(BUILD)/bin/trk-vectors
vectors-emit: $(TEST_EXTRA_DEPS_vectors-emit)
	@d=$$(mktemp -d) || exit 1; st=0; \
	printf 'case no_such_kind e1\nin a 1\nout b 2\nout c 3 4\nend\n' > $$d/unknown.vec; \
	$(BUILD)/bin/trk-vectors --emit $$d/unknown.vec > $$d/unknown.out || st=1; \
	if grep -q '^out ' $$d/unknown.out; then echo "vectors-emit: an unimplemented kind's expected outputs were written back"; st=1; fi; \
	[ "$$(grep -c '^# not computed' $$d/unknown.out)" = 2 ] || { echo "vectors-emit: missing '# not computed' lines"; st=1; }; \
	if [ -f $(VECTORS_DIR)/imm.vec ] || { echo "vectors-emit: $(VECTORS_DIR)/imm.vec missing"; st=1; false; }; then \
	  $(BUILD)/bin/trk-vectors --emit $(VECTORS_DIR)/imm.vec > $$d/imm.out || st=1; \
	  n_case=$$(grep -c '^case ' $$d/imm.out); n_out=$$(grep -c '^out ' $$d/imm.out); \
	  n_nc=$$(grep -c '^# not computed' $$d/imm.out); \
	  n_want=$$(grep -c '^out ' $(VECTORS_DIR)/imm.vec); \
	  [ $$((n_out + n_nc)) = $$n_want ] || { echo "vectors-emit: imm.vec: $$n_out out + $$n_nc not computed != $$n_want"; st=1; }; \
	  echo "vectors-emit: imm.vec: $$n_case cases, $$n_out outputs computed, $$n_nc left out"; \
	fi; \
	rm -rf $$d; \
	if [ $$st = 0 ]; then echo "vectors-emit: --emit writes only computed outputs"; \
	else echo "vectors-emit: FAILED"; exit 1; fi
