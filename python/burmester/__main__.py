"""``python -m burmester``: the command-line tool (see ``burmester.cli``)."""

import sys

from burmester.cli import main

if __name__ == "__main__":
    sys.exit(main())
