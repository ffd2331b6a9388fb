"""``python -m dmdvox``: the same command line as ``dmdvox``."""

import sys

from .cli import main

sys.exit(main())
