"""``python -m rigidmech``: the command line (see :mod:`rigidmech.scenes.cli`).

The ``rigidmech`` console script of ``pyproject.toml`` also points at :func:`main`.
"""

import sys

from rigidmech.scenes.cli import main

__all__ = ["main"]

if __name__ == "__main__":
    sys.exit(main())
