# mk/docs-links.mk - `make docs-links`: every relative link of the Markdown
# files (README, CHANGELOG, docs/, the rest in git) names a file of the
# repository and, with a #fragment, a heading of it (tools/scripts/
# docs_links.py: GitHub's anchors), a step of `make test`.
TEST_EXTRA += docs-links
TEST_EXTRA_DEPS_docs-links :=
.PHONY: docs-links
docs-links:
	@python3 tools/scripts/docs_links.py $$(git ls-files '*.md' 2>/dev/null || ls *.md docs/*.md)
