"""``python -m tests.bench`` (from the repository root): see :mod:`tests.bench`."""

from tests.bench.cli import main

raise SystemExit(main())
