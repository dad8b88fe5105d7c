"""The labels' bitmap font: every printable ASCII letter, cut at the picture's edges."""

from __future__ import annotations

import string

import numpy as np

from typed_mjcf._sim.font import GLYPH_HEIGHT, draw_text, text_size

INK = (200, 100, 50)


def _drawn(text: str, x: int = 0, y: int = 0, size: tuple[int, int] = (9, 40)) -> np.ndarray:
    image = np.zeros((*size, 3), dtype=np.uint8)
    draw_text(image, text, x, y, INK)
    return np.all(image == INK, axis=2)


def test_a_letter_is_its_bitmap() -> None:
    assert _drawn("T")[:7, :5].tolist() == [[c == "#" for c in row] for row in (
        "#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#..")]


def test_every_printable_letter_has_a_glyph_of_its_own() -> None:
    printable = [c for c in string.printable if c.isprintable()]
    glyphs = {c: _drawn(c).tobytes() for c in printable}
    unknown = _drawn("\u00e9").tobytes()  # not ASCII: drawn as "?"
    assert unknown == glyphs["?"]
    assert len({glyphs[c] for c in printable if c != " "}) == len(printable) - 1
    assert not _drawn(" ").any()


def test_size_and_scale() -> None:
    assert text_size("abc") == (17, GLYPH_HEIGHT)
    assert text_size("abc", 2) == (34, 2 * GLYPH_HEIGHT)
    image = np.zeros((30, 60, 3), dtype=np.uint8)
    draw_text(image, "abc", 1, 2, INK, scale=2)
    rows, columns = np.nonzero(np.all(image == INK, axis=2))
    assert columns.min() >= 1 and columns.max() < 1 + 34 and rows.min() >= 2


def test_text_outside_the_picture_is_cut() -> None:
    assert _drawn("WIDE TEXT", x=-3, y=-2, size=(5, 12)).any()
    assert not _drawn("X", x=100).any() and not _drawn("X", y=-50).any()
