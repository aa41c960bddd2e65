"""``python -m teachraster ...``: the classroom export command line (see :mod:`teachraster.cli`)."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
