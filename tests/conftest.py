"""The ``slow`` marker: which test modules the edit loop (``pytest -m "not slow"``) leaves out.

One list, each module (or ``module::test``) with what makes it slow (another program run over
many files, a language server, MuJoCo or dm_control over a whole corpus, a scaling or fuzzing
run). ``nox -s tests`` and plain
``pytest`` run everything; the list only chooses what ``-m "not slow"`` deselects.
"""

from __future__ import annotations

import functools
import gc
import os
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.support.typecheck import Checker, Diagnostic, TypedCodeRun, run_typed_code
from tests.support.user_code import UserCode, check_user_code, user_project

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
    "typing/test_runtime_stubs.py": "stubtest, mypy and pyright twice, pyright's language server",
    "typing/test_positive.py": "mypy and pyright",
    "typing/test_any_audit.py": "pyright over the package",
    "cli/test_to_python.py": "to-python over the corpus",
    "cli/test_to_python_types.py": "mypy and pyright over the corpus in Python",
    "codegen/test_mujoco_stubs.py": "pybind11-stubgen and mypy's stubgen",
    "codegen/test_drift.py": "the generator over MuJoCo's grammar",
    "codegen/test_facts_errors.py": "the generator's sync, once per mistake",
    "codegen/test_language.py::test_a_new_fact_goes_from_facts_toml_to_the_runtime":
        "the generator, twice, on a copy of the repository",
    "codegen/test_type_drift.py": "MuJoCo's parser over the schema's attributes (drift probe)",
    "dm_control/test_dm_control_tests.py": "dm_control's own test suite",
    "dm_control/test_parity.py": "dm_control beside typed-mjcf over the corpus",
    "dm_control/test_compat.py::test_dm_controls_own_references_read_alike":
        "dm_control's own mjcf, in a subprocess",
    "dm_control/test_composer.py::test_environments_with_cameras_run":
        "dm_control's environments with cameras: an image rendered at each of 1040 steps",
    "fidelity/test_corpus_validate.py": "MuJoCo compiles the corpus",
    "fidelity/test_defaults_corpus.py": "MuJoCo compiles the corpus",
    "fidelity/test_round_trip.py": "round trips of the corpus",
    "fidelity/test_rules.py": "MuJoCo compiles two models or more per rule of the tables",
    "fidelity/test_refusal_fuzz.py": "MuJoCo compiles mutants of the corpus, in a worker",
    "fidelity/test_properties.py": "hypothesis",
    "runtime/test_corpus.py": "the corpus, compiled",
    "runtime/test_release_driven.py": "the release tests again, in a fresh interpreter per "
                                      "older release",
    "bench/test_bench_smoke.py": "the benchmark suite, tiny sizes",
    "variation/test_ray.py": "starts a local Ray cluster (tens of seconds; nox -s ray)",
    "warp/test_worlds.py": "MuJoCo Warp's kernels (built, then stepped on the CPU device)",
    "warp/test_refusals.py": "MuJoCo Warp's put_model, once per element taken out",
    "safety/test_fuzz.py": "thousands of mutated models",
    "safety/test_file_races.py::test_a_writer_swapping_links_in_a_loop_reads_nothing_outside":
        "reads for 4 seconds while a thread swaps links",
    "render/test_gl.py::test_physics_render_after_mujoco_chose_glfw_says_to_set_mujoco_gl_first":
        "MuJoCo's renderer in a subprocess",
    "safety/test_crashes.py::test_plugins_mujoco_answers_are_not_refused_for_crashing":
        "MuJoCo in a child process per case",
    "cli/test_diff.py::test_a_model_does_not_differ_from_itself": "the corpus, diffed",
    "cli/test_diff.py::test_an_edit_shows_as_exactly_that_edit": "the corpus, edited",
    "cli/test_diff.py::test_formatting_does_not_show": "the corpus, formatted",
    "cli/test_fmt.py::test_the_formatted_model_compiles_the_same": "the corpus, compiled",
    "safety/test_errors.py::test_repeated_default_sections_take_linear_work":
        "every Python line of two parses counted",
    "safety/test_entities.py::test_entity_bombs_use_no_memory": "entity expansion bombs",
    "fidelity/test_validate.py::test_validate_is_linear_in_the_number_of_elements":
        "models of growing size",
    "test_generated_api.py::test_every_attribute_mujoco_lists_is_a_typed_property":
        "every attribute through MuJoCo",
    "dm_control/test_builders.py": "dm_control's builders, in two subprocesses",
    "dm_control/test_composer.py::test_manipulation_features_tasks_run":
        "dm_control's environments, in a subprocess",
    "runtime/test_corpus_asset_routes.py": "the corpus, loaded back two ways",
    "safety/test_resources.py": "inputs of 100,000 elements, in fresh interpreters",
    "safety/test_zip.py::test_zip_bombs_take_bounded_memory": "zip bombs, in subprocesses",
    "cli/test_fmt.py::test_formatting_twice_changes_nothing": "the corpus, formatted",
    "cli/test_fmt.py::test_the_exporters_canonical_text_is_formatted": "the corpus, exported",
    "cli/test_fmt.py::test_fmt_changes_few_lines_of_the_corpus": "the corpus, formatted",
    "cli/test_linear_paths.py": "every Python line of fmt and to-python counted, twice",
    "safety/test_export_signals.py": "exports in subprocesses, signalled",
    "safety/test_compile_limits.py::test_every_corpus_model_compiles_within_the_default_limits":
        "the corpus, read",
}


# How pytest-xdist shares the tests out (with -n; pyproject's addopts: --dist loadgroup
# --no-loadscope-reorder, and pytest_xdist_make_scheduler below). A module's tests go to one
# worker together, so its module-scoped fixtures (a type checker's run, a language server,
# the corpus compiled) are built once; the modules in SPREAD are the exception: their tests
# are independent and long, each goes to whichever worker is free. The work starts with
# FIRST, in its order (the longest first, in CPU seconds, measured with `pytest -n 2
# --durations=60`), so that no long test starts last while the other worker idles.
SPREAD = {
    "dm_control/test_composer.py",  # each test runs its environments in its own subprocess
}
# Modules that share a session-scoped fixture run with the module named, on its worker.
GROUPS = {
    # typed_code_run (below): one mypy and one pyright run
    "typing/test_mujoco_stubs.py": "typing/test_typecheck.py",
    "cli/test_to_python_types.py": "typing/test_typecheck.py",
    # user_code_reports (below): one mypy and one pyright run over the user's project
    "test_readme.py": "typing/test_runtime_stubs.py",
}
FIRST = (
    "typing/test_typecheck.py",  # with test_mujoco_stubs.py, test_to_python_types.py
    # (GROUPS): the corpus in Python, then mypy and pyright side by side: ~90 s CPU
    "typing/test_mujoco_stubs.py",
    "dm_control/test_composer.py",  # 5 units (SPREAD) of 11 to 26 s CPU
    "typing/test_runtime_stubs.py",  # with test_readme.py (GROUPS): stubtest, mypy and
    # pyright over the user's project twice, the language server twice: ~75 s CPU
    "safety/test_resources.py",
    "cli/test_to_python_types.py",
    "bench/test_bench_smoke.py",
    "dm_control/test_builders.py",
    "cli/test_fmt.py",
    "typing/test_any_audit.py",
    "codegen/test_language.py",  # the generator twice on a copy of the repository: ~20 s CPU
    "runtime/test_corpus.py",
    "runtime/test_corpus_asset_routes.py",
    "test_readme.py",
    "fidelity/test_defaults_corpus.py",
    "cli/test_to_python.py",
    "fidelity/test_properties.py",
    "cli/test_diff.py",
    "codegen/test_drift.py",
    "codegen/test_facts_errors.py",
    "typing/test_ide.py",
)


@pytest.fixture(scope="session")
def typed_code_run(tmp_path_factory: pytest.TempPathFactory) -> TypedCodeRun:
    """One mypy and one pyright run per session with the repository's configuration: the
    typed code, the negative cases, and to-python's code of the corpus (``GROUPS`` keeps
    the modules that read it on one worker)."""
    from tests.support.to_python_corpus import corpus_modules  # MuJoCo: not at collection

    modules = corpus_modules(tmp_path_factory.mktemp("to_python"))
    return TypedCodeRun.split(run_typed_code(tmp_path_factory.mktemp("mypy_cache"), modules),
                              modules)


@pytest.fixture(scope="session")
def typed_code_reports(typed_code_run: TypedCodeRun) -> dict[Checker, list[Diagnostic]]:
    """What the checkers said of the typed code and the negative cases."""
    return typed_code_run.typed_reports


@pytest.fixture(scope="session")
def user_code(tmp_path_factory: pytest.TempPathFactory) -> UserCode:
    """A user's project of the README's code, ``examples/`` and the negative cases."""
    return user_project(tmp_path_factory.mktemp("user_project"))


@pytest.fixture(scope="session")
def user_code_reports(user_code: UserCode, tmp_path_factory: pytest.TempPathFactory,
                      ) -> dict[Checker, list[Diagnostic]]:
    """mypy and pyright on ``user_code`` against this environment's ``typed_mjcf`` (the
    source tree): test_readme.py reads them, test_runtime_stubs.py compares them with the
    wheel's layout (``GROUPS`` keeps the two modules on one worker)."""
    return check_user_code(user_code, sys.executable, tmp_path_factory.mktemp("mypy_cache"))


def _module(item: pytest.Item) -> str:
    return _relative(item.path)


@functools.cache
def _relative(path: Path) -> str:
    """A test file's path in tests/ (once per file: ``relative_to`` for each of the 6,000
    items, twice, cost every pytest process 0.2 s of its collection)."""
    return path.relative_to(TESTS).as_posix()


@pytest.hookimpl(wrapper=True)
def pytest_collection_modifyitems(items: list[pytest.Item]) -> Iterator[None]:
    # before the other plugins: -m "not slow" deselects by these marks
    for item in items:
        module = _module(item)
        function = getattr(item, "originalname", item.name)
        if module in SLOW or f"{module}::{function}" in SLOW:
            item.add_marker(pytest.mark.slow)
    yield
    # after them (pytest orders items by fixtures too): the longest first, stable otherwise
    rank = {module: at for at, module in enumerate(FIRST)}
    items.sort(key=lambda item: rank.get(_module(item), len(FIRST)))


@pytest.hookimpl(trylast=True)
def pytest_collection_finish(session: pytest.Session) -> None:
    """Every test module, the grammar tables and what they import are loaded now and live to
    the end: frozen out of the cyclic collector's reach, so that each full collection (the
    ones a test's work triggers, the benchmark's before each sample) scans only what the tests
    made since, not these few hundred thousand objects again."""
    gc.collect()
    gc.freeze()


def work_unit(nodeid: str) -> str:
    """The unit of work a test goes to a worker in: its module, its module's group, or
    itself (SPREAD)."""
    module = nodeid.partition("::")[0].removeprefix(f"{TESTS.name}/")
    if module in SPREAD:
        return nodeid
    return GROUPS.get(module, module)


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config: pytest.Config, log: object) -> object:
    """``--dist loadgroup``: xdist's load-scope scheduling by ``work_unit`` (its own
    loadgroup reads ``xdist_group`` marks into node ids, which pytest 9.2's node ids ignore)."""
    if config.getvalue("dist") != "loadgroup":
        return None
    from xdist.scheduler import LoadScopeScheduling

    class ByWorkUnit(LoadScopeScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return work_unit(nodeid)

    return ByWorkUnit(config, log)  # type: ignore[arg-type]  # xdist's Producer
