# mk/params-doc.mk - `make params-doc`: docs/parameters.md against the
# defaults and the field names of the check (tests/params_doc.sh), a step of
# `make test`.
TEST_EXTRA += params-doc
TEST_EXTRA_DEPS_params-doc := $(BUILD)/bin/trk-lcm-bridge
.PHONY: params-doc
params-doc: $(TEST_EXTRA_DEPS_params-doc)
	@sh tests/params_doc.sh $(BUILD)/bin
