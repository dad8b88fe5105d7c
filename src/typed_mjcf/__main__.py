"""``python -m typed_mjcf``: the ``typed-mjcf`` command line."""

from typed_mjcf.cli import main

raise SystemExit(main())
