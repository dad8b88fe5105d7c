"""pyright's rule for the documentation of a parameter (what an editor shows for keyword ``p``
of a call): ``extractParameterDocumentation`` and ``cleanAndSplitDocString`` of pyright's
``docStringUtils``, repeated."""

from __future__ import annotations


def clean_and_split(doc: str) -> list[str]:
    """pyright's ``cleanAndSplitDocString``: tabs expanded, the common indent of the lines
    after the first removed, blank lines trimmed at both ends."""
    lines = doc.replace("\r", "").replace("\t", " " * 8).split("\n")
    indents = [len(line) - len(line.lstrip()) for i, line in enumerate(lines)
               if (len(lines) <= 1 or i > 0) and line.strip()]
    indent = min(indents, default=0)
    cleaned = [line.strip() if i == 0 else line[indent:].rstrip()
               for i, line in enumerate(lines)]
    while cleaned and not cleaned[0]:
        cleaned.pop(0)
    while cleaned and not cleaned[-1]:
        cleaned.pop()
    return cleaned


def pyright_parameter_doc(doc: str, name: str) -> str | None:
    """The documentation pyright shows for parameter ``name`` (hover, signature help)."""
    for line in clean_and_split(doc):
        text = line.strip()
        for prefix in ("@param ", ":param "):
            at = text.find(prefix + name)
            if at >= 0:
                return text[at + 7:]
        for suffix in (": ", " ("):
            at = text.find(name + suffix)
            if at >= 0:
                return text[at:]
    return None
