# ---- the book: the course as a static site, read offline in a browser ------------
#
# `make book` writes BOOK (build/book/, open index.html): the title page,
# each chapter's lesson and lab, the measurements, the scene format and the
# guides, with typeset equations, listings of the source and prev / next
# links (tools/book/build.sh).  `make check-book` loads every page in
# headless Chromium and fails on a console error, an image that does not
# load, an equation not typeset, a link or anchor that leads nowhere, or a
# page wider than a 400-pixel window; its screenshots go to BOOK_CHECK.
# The packages come from Debian (tools/deps.sh groups book and book-check).
# `make test` runs check-book when Chromium is installed (test-book).

BOOK ?= build/book
BOOK_CHECK ?= build/book-check

# The book is rebuilt when any file it may show or link has changed.
BOOK_INPUTS := $(shell find README.md chapters docs common tests tools -type f 2>/dev/null)

.PHONY: book check-book test-book
book: $(BOOK)/index.html

$(BOOK)/index.html: $(BOOK_INPUTS)
	@tools/deps.sh "$(CC)" book
	@tools/book/build.sh $(BOOK)

check-book: $(BOOK)/index.html
	@tools/deps.sh "$(CC)" book-check
	@node tools/book/check.mjs $(BOOK) $(BOOK_CHECK)

test-book:
	@if command -v chromium >/dev/null 2>&1; then $(MAKE) --no-print-directory check-book; \
	else echo "make test: check-book skipped: no chromium (make check-book installs it)"; fi
