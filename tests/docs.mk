# docs.mk — the documents' links.
#
#   check-docs   every relative Markdown link in README.md and docs/ resolves to
#                a file and, with an anchor, to one of its headings (GitHub's
#                slugs); the checker is first shown broken links it must reject;
#                and no document refers to an issue by number or to a document
#                outside the repository (tests/docs/check_refs.sh, shown one
#                of each first).

.PHONY: check-docs
CHECKS += check-docs

check-docs:
	@tests/docs/check_refs.sh --selftest
	@tests/docs/check_links.sh --selftest
