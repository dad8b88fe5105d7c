"""The ``slow`` marker: which test modules the edit loop (``pytest -m "not slow"``) leaves out.

One list, each module (or ``module::test``) with what makes it slow (another program run over
many files, a language server, MuJoCo or dm_control over a whole corpus, a scaling or fuzzing
run). ``nox -s tests`` and plain
``pytest`` run everything; the list only chooses what ``-m "not slow"`` deselects.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

# MuJoCo picks its OpenGL back end when first imported: EGL renders without a display (on
# Mesa's software EGL where there is no GPU), so the tests that render (the README's example,
# tests/physics, tests/render) run on headless machines. A back end the user chose is kept.
os.environ.setdefault("MUJOCO_GL", "egl")

TESTS = Path(__file__).resolve().parent

SLOW = {
    "test_readme.py": "mypy and pyright over the README's examples",
    "test_examples.py": "runs the examples: compiles and simulates",
    "typing/test_typecheck.py": "mypy and pyright over tests/typing",
    "typing/test_mujoco_stubs.py": "mypy and pyright over the mujoco stub cases",
    "typing/test_ide.py": "pyright's language server",
    "typing/test_positive.py": "mypy and pyright",
    "typing/test_any_audit.py": "pyright over the package",
    "cli/test_to_python.py": "to-python over the corpus",
    "cli/test_to_python_types.py": "mypy and pyright over the corpus in Python",
    "codegen/test_mujoco_stubs.py": "pybind11-stubgen and mypy's stubgen",
    "codegen/test_drift.py": "the generator over MuJoCo's grammar",
    "codegen/test_type_drift.py": "MuJoCo's parser over the schema's attributes (drift probe)",
    "dm_control/test_dm_control_tests.py": "dm_control's own test suite",
    "dm_control/test_parity.py": "dm_control beside typed-mjcf over the corpus",
    "dm_control/test_composer.py::test_environments_with_cameras_run":
        "dm_control's environments with cameras: an image rendered at each of 2000 steps",
    "fidelity/test_corpus_validate.py": "MuJoCo compiles the corpus",
    "fidelity/test_defaults_corpus.py": "MuJoCo compiles the corpus",
    "fidelity/test_round_trip.py": "round trips of the corpus",
    "fidelity/test_properties.py": "hypothesis",
    "runtime/test_corpus.py": "the corpus, compiled",
    "bench/test_bench_smoke.py": "the benchmark suite, tiny sizes",
    "safety/test_fuzz.py": "thousands of mutated models",
    "cli/test_diff.py::test_a_model_does_not_differ_from_itself": "the corpus, diffed",
    "cli/test_diff.py::test_an_edit_shows_as_exactly_that_edit": "the corpus, edited",
    "cli/test_diff.py::test_formatting_does_not_show": "the corpus, formatted",
    "cli/test_fmt.py::test_the_formatted_model_compiles_the_same": "the corpus, compiled",
    "safety/test_errors.py::test_repeated_default_sections_take_linear_time": "a 250 kB model",
    "safety/test_entities.py::test_entity_bombs_use_no_memory": "entity expansion bombs",
    "fidelity/test_validate.py::test_validate_is_linear_in_the_number_of_elements":
        "models of growing size",
    "test_generated_api.py::test_every_attribute_mujoco_lists_is_a_typed_property":
        "every attribute through MuJoCo",
}


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    for item in items:
        module = item.path.relative_to(TESTS).as_posix()
        function = getattr(item, "originalname", item.name)
        if module in SLOW or f"{module}::{function}" in SLOW:
            item.add_marker(pytest.mark.slow)

