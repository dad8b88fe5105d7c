"""A pytest plugin for ``public_projects.py`` (``-p tests.dm_control.install_plugin``): loaded
before pytest collects anything, it makes ``dm_control.mjcf`` typed-mjcf's for the run.
Not a test module, and not loaded by the project's own test runs."""

from __future__ import annotations

import typed_mjcf

typed_mjcf.install_as_dm_control_mjcf()
