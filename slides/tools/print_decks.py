#!/usr/bin/env python3
"""print_decks.py BASE_URL PRINT.html DECK.pdf [PRINT.html DECK.pdf ...]

Prints decks' print HTML (pandoc's, not self-contained: figures and fonts are
read from BASE_URL) to PDF with WeasyPrint, all in this one process: starting
Python and importing WeasyPrint costs more than half of printing one deck.
A deck that fails is named, the others are still printed; exit 1 if any failed.
WeasyPrint's warnings (CSS it does not use, KaTeX's and pandoc's) go to stderr.
"""
import os
import sys
import time

import weasyprint


def main():
    if len(sys.argv) < 4 or len(sys.argv) % 2:
        sys.exit("usage: print_decks.py BASE_URL PRINT.html DECK.pdf [PRINT.html DECK.pdf ...]")
    base = sys.argv[1]
    failed = 0
    for html, pdf in zip(sys.argv[2::2], sys.argv[3::2]):
        t0 = time.time()
        try:
            weasyprint.HTML(filename=html, base_url=base).write_pdf(pdf)
        except Exception as e:  # one deck's failure must not hide the others'
            print(f"print-decks: {html} -> {pdf} failed: {type(e).__name__}: {e}", file=sys.stderr, flush=True)
            if os.path.exists(pdf):
                os.remove(pdf)  # half-written: no stamp may vouch for it
            failed = 1
            continue
        print(f"print-decks: {pdf} ({time.time() - t0:.1f} s)", flush=True)
    sys.exit(failed)


if __name__ == "__main__":
    main()
