"""The site's tests need the built site: ``nox -s docs`` builds it and runs them (the
suite of ``nox -s tests`` does not collect them)."""

from __future__ import annotations

import os

collect_ignore = [] if os.environ.get("TYPED_MJCF_DOCS_SITE") else ["test_site.py"]
