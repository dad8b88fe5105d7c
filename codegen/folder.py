"""A generated folder kept equal to a mapping of its files: what differs, and making it so."""

from __future__ import annotations

from pathlib import Path


def stale(files: dict[str, str], directory: Path, pattern: str = "*") -> list[str]:
    """Paths under ``directory`` (those matching ``pattern``) that differ from ``files``,
    are missing or are extra."""
    on_disk: set[str] = ({p.relative_to(directory).as_posix() for p in directory.rglob(pattern)
                if p.is_file()} if directory.is_dir() else set())
    differ = [name for name, text in files.items()
              if not (directory / name).is_file()
              or (directory / name).read_text(encoding="utf-8") != text]
    return sorted(set(differ) | (on_disk - set(files)))


def write(files: dict[str, str], directory: Path, pattern: str = "*") -> list[str]:
    """Make ``directory`` hold exactly ``files`` (of those matching ``pattern``); the paths
    that changed."""
    changed = stale(files, directory, pattern)
    for name in changed:
        path = directory / name
        if name in files:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(files[name], encoding="utf-8", newline="\n")
        else:
            path.unlink()
    return changed
