"""The installed MuJoCo's release: what its grammar lacks or types otherwise, and the
behaviour no grammar row states, applied to the core's tables when the grammar is loaded
(the generated tables call :func:`follow_installed_release`); the core knows nothing of
releases."""

from __future__ import annotations

from collections.abc import Mapping

from typed_mjcf._core.tree import Element, explain_refusals
from typed_mjcf._releases.facts import apply as apply_facts
from typed_mjcf._releases.gating import note, restrict, value_note


def follow_installed_release(classes: Mapping[str, type[Element]]) -> None:
    """Take out of ``classes`` (every generated class) what the release in use lacks, retype
    what it types otherwise, follow its behaviour, and say so in refusals."""
    restrict(classes)
    apply_facts()
    explain_refusals(note, value_note)
