# mk/structure.mk - `make structure`: no circle among the source files of src/
# and tools/ (tools/scripts/structure.py: "A uses B" from includes and from the
# identifiers A's translation unit sees), a step of `make test`.
# `make structure-dot`: the drawing, $(BUILD)/structure.dot (Graphviz:
# dot -Tsvg build/structure.dot -o structure.svg).
TEST_EXTRA += structure
TEST_EXTRA_DEPS_structure :=
.PHONY: structure structure-dot
structure:
	@python3 tools/scripts/structure.py --check .
structure-dot:
	@mkdir -p $(BUILD)
	@python3 tools/scripts/structure.py --dot $(BUILD)/structure.dot . >/dev/null
	@echo "wrote $(BUILD)/structure.dot"
