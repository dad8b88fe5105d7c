"""The report: markdown tables of medians, ratios to the raw-lxml floor, growth with size, and
the performance targets met or missed."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from tests.bench.bind import render_bind
from tests.bench.timing import Case, Sample, SizeResult, growth_exponent
from tests.bench.variation import render_variation

# Targets of the performance issue (ratios measured in one run).
W1_TYPED_MAX = 2.5  # typed-mjcf add_<tag>() / lxml, N = 5,000 and 20,000, named and unnamed
W1_GENERIC_MAX = 3.0  # typed-mjcf add("<tag>") / lxml
W1_GROWTH_MAX = 4.4  # time(20,000) / time(5,000): linear is 4.0, 10 % slack
W3_GROWTH_MAX = 5.5  # time(K=500) / time(K=100): linear is 5.0, the same 10 % slack
W2_MAX = 3.0  # typed-mjcf parse + export / lxml parse + serialise (robot files)
IMPORT_MAX = 0.3  # seconds
# Issue 38's targets, for every typed-mjcf build measured (the compiled build is the one
# that issue sets them for): the ratios to the floor each names, in one run.
W1_NAMED_MAX = 1.6  # W1 add_<tag>() named, N = 5,000, build + export / lxml
W2_TEXT_MAX = 8.0  # W2 of W1's dense text (N = 5,000) / lxml: no robot file is that dense
W3_MAX = 2.5  # W3 attach K = 500 + export / lxml
FIRST_BIND_MAX = 1.5  # physics.bind(joints).qpos, first bind / mj_name2id + slices
FROM_MODEL_MAX = 1.2  # Physics.from_mjcf_model / MjModel.from_xml_string of the same text


@dataclass
class Results:
    meta: dict[str, Any] = field(default_factory=dict)
    w1: list[Case] = field(default_factory=list)
    w2: list[Case] = field(default_factory=list)
    w3: list[Case] = field(default_factory=list)
    imports: list[dict[str, Any]] = field(default_factory=list)
    importtime: list[dict[str, Any]] = field(default_factory=list)
    memory: list[dict[str, Any]] = field(default_factory=list)
    validity: list[dict[str, Any]] = field(default_factory=list)
    bind: list[dict[str, Any]] = field(default_factory=list)
    variation: list[dict[str, Any]] = field(default_factory=list)

    def as_json(self) -> dict[str, Any]:
        def cases(items: list[Case]) -> list[dict[str, Any]]:
            return [{"workload": c.workload, "library": c.library, "title": c.title,
                     "api": c.api, "naming": c.naming, "source": c.source, "note": c.note,
                     "sizes": [r.as_json() for _, r in sorted(c.sizes.items())]}
                    for c in items]

        return {"meta": self.meta, "W1": cases(self.w1), "W2": cases(self.w2),
                "W3": cases(self.w3), "import": self.imports, "importtime": self.importtime,
                "memory": self.memory, "validity": self.validity, "bind": self.bind,
                "variation": self.variation,
                "targets": [t.as_json() for t in targets(self)]}


    @classmethod
    def from_json(cls, data: dict[str, Any]) -> Results:
        """A saved run (``--json``), to render again (``--from-json``)."""

        def cases(items: list[dict[str, Any]]) -> list[Case]:
            found = []
            for item in items:
                case = Case(item["workload"], item["library"], item["title"], api=item["api"],
                            naming=item["naming"], source=item["source"], note=item["note"])
                for r in item["sizes"]:
                    case.sizes[r["size"]] = SizeResult(
                        r["size"],
                        [Sample(s["make"], s["export"], s["make_cpu"], s["export_cpu"],
                                s.get("gc", 0.0), s.get("full_collections", 0))
                         for s in r["samples"]],
                        skipped=r["skipped"] or "", estimate=r["estimate"], valid=r["valid"],
                        invalid=r["invalid"] or "", error=r["error"] or "")
                found.append(case)
            return found

        return cls(meta=data["meta"], w1=cases(data["W1"]), w2=cases(data["W2"]),
                   w3=cases(data["W3"]), imports=data["import"], importtime=data["importtime"],
                   memory=data["memory"], validity=data["validity"],
                   bind=data.get("bind", []), variation=data.get("variation", []))


# ----------------------------------------------------------------------------- formatting

CLOCK_WORDS = {
    "cpu": "process CPU time (the libraries are single-threaded here; CPU time leaves out "
           "the time other processes held the core, which on a shared machine swings "
           "wall-clock medians by up to 2x: see the CPU/wall column)",
    "wall": "wall-clock time",
}


def ms(seconds: float | None) -> str:
    if seconds is None:
        return "-"
    value = seconds * 1000
    if value >= 100:
        return f"{value:,.0f}"
    if value >= 10:
        return f"{value:.1f}"
    return f"{value:.2f}"


def ratio(value: float | None, floor: float | None) -> float | None:
    if value is None or floor is None or floor <= 0:
        return None
    return value / floor


def times(x: float | None) -> str:
    return "-" if x is None else f"{x:.2f}x"


def table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> str:
    widths = [max(len(str(r[i])) for r in [header, *rows]) for i in range(len(header))]

    def line(cells: Sequence[str]) -> str:
        return "| " + " | ".join(str(c).ljust(w) for c, w in zip(cells, widths)) + " |"

    rule = "|" + "|".join("-" * (w + 2) for w in widths) + "|"
    return "\n".join([line(header), rule, *(line(r) for r in rows)])


def cell(result: SizeResult | None, floor: SizeResult | None, key: str = "total") -> str:
    if result is None:
        return ""
    if result.error:
        return "failed"
    if not result.samples:
        if result.estimate is not None:
            return f"skipped (est. {result.estimate:,.0f} s wall)"
        return "skipped"
    value = result.median(key)
    r = ratio(value, None if floor is None else floor.median(key))
    return f"{ms(value)}" + (f" ({times(r)})" if r is not None else "")


def growth(case: Case, sizes: Sequence[int]) -> tuple[float | None, float | None]:
    """time(last) / time(previous) over the two largest of ``sizes``, and its exponent."""
    if len(sizes) < 2:
        return None, None
    a, b = case.sizes.get(sizes[-2]), case.sizes.get(sizes[-1])
    ta = None if a is None else a.median()
    tb = None if b is None else b.median()
    if ta is None or tb is None:
        return None, None
    return tb / ta, growth_exponent(sizes[-2], ta, sizes[-1], tb)


def floor_case(cases: Sequence[Case], like: Case) -> Case | None:
    for c in cases:
        if c.library == "lxml" and c.naming == like.naming and c.source == like.source:
            return c
    return None


def _repeats(case: Case, sizes: Sequence[int]) -> str:
    return "/".join(str(len(case.sizes[n].samples)) if n in case.sizes else "-" for n in sizes)


# ----------------------------------------------------------------------------- sections


def sized_table(cases: Sequence[Case], sizes: Sequence[int], unit: str) -> str:
    header = ["library", "API", "names"] if cases and cases[0].workload == "W1" else ["library"]
    header += [f"{unit}={n:,}" for n in sizes]
    header += [f"{sizes[-1]:,}/{sizes[-2]:,} (exp.)" if len(sizes) > 1 else "growth", "runs"]
    rows = []
    for case in cases:
        floor = floor_case(cases, case)
        row = [case.title] + ([case.api or "-", case.naming] if "API" in header else [])
        for n in sizes:
            row.append(cell(case.sizes.get(n), None if floor is None or floor is case
                            else floor.sizes.get(n)))
        g, p = growth(case, sizes)
        row.append("-" if g is None else f"{g:.2f} ({p:.2f})")
        row.append(_repeats(case, sizes))
        rows.append(row)
    return table(header, rows)


def phase_table(cases: Sequence[Case], size: int, unit: str) -> str:
    header = ["library", "API", "names"] if cases and cases[0].workload == "W1" else ["library"]
    header += ["make ms", "export ms", "make x floor", "export x floor", "cyclic GC ms (full)",
               "CPU/wall"]
    rows = []
    for case in cases:
        result = case.sizes.get(size)
        if result is None or not result.samples:
            continue
        floor = floor_case(cases, case)
        floor_result = None if floor is None else floor.sizes.get(size)
        row = [case.title] + ([case.api or "-", case.naming] if "API" in header else [])
        make, export = result.median("make"), result.median("export")
        row += [ms(make), ms(export)]
        if floor_result is not None and floor is not case:
            row += [times(ratio(make, floor_result.median("make"))),
                    times(ratio(export, floor_result.median("export")))]
        else:
            row += ["-", "-"]
        row.append(_collector(result))
        cpu, wall = result.median(clock="cpu"), result.median(clock="wall")
        row.append("-" if not cpu or not wall else f"{cpu / wall:.2f}")
        rows.append(row)
    return f"Phases at {unit}={size:,} (median ms):\n\n" + table(header, rows)


def _collector(result: SizeResult) -> str:
    """The collector's median time per run, with its median count of full collections."""
    medians = result.median_gc()
    return "-" if medians is None else f"{ms(medians[0])} ({medians[1]:g})"


def collector_table(cases: Sequence[Case], sizes: Sequence[int], unit: str) -> str:
    """Time inside CPython's cyclic collector per run, and growth with that time left out."""
    header = ["library", "API", "names"] + [f"{unit}={n:,}" for n in sizes]
    header.append(f"{sizes[-1]:,}/{sizes[-2]:,} less GC")
    rows = []
    for case in cases:
        row = [case.title, case.api or "-", case.naming]
        row += [_collector(case.sizes[n]) if n in case.sizes else "-" for n in sizes]
        a, b = case.sizes.get(sizes[-2]), case.sizes.get(sizes[-1])
        less: list[float] = []
        for result in (a, b):
            total, collected = (None, None) if result is None else (
                result.median(), result.median_gc())
            if total is not None and collected is not None:
                less.append(total - collected[0])
        row.append(f"{less[1] / less[0]:.2f}" if len(less) == 2 and less[0] > 0 else "-")
        rows.append(row)
    return table(header, rows)


def w2_table(cases: Sequence[Case]) -> str:
    header = ["source", "library", "parse ms", "export ms", "total ms", "x floor", "runs",
              "output compiles"]
    rows = []
    for case in cases:
        result = next(iter(case.sizes.values()), None)
        if result is None:
            continue
        floor = floor_case(cases, case)
        floor_result = None if floor is None else next(iter(floor.sizes.values()), None)
        r = None
        if floor_result is not None and floor is not case:
            r = ratio(result.median(), floor_result.median())
        valid = {True: "yes", False: "NO", None: "-"}[result.valid]
        if result.valid is False and result.invalid:
            valid += f" ({result.invalid[:70]})"
        if result.error:
            valid = f"failed: {result.error[:70]}"
        rows.append([case.source, case.title, ms(result.median("make")),
                     ms(result.median("export")), ms(result.median()),
                     times(r) if floor is not case else "1.00x (floor)",
                     str(len(result.samples)), valid])
    return table(header, rows)


# ----------------------------------------------------------------------------- targets


@dataclass
class Target:
    text: str
    value: str
    met: bool | None  # None: not measured in this run

    def as_json(self) -> dict[str, Any]:
        return {"target": self.text, "value": self.value, "met": self.met}


def is_typed(case: Case) -> bool:
    """A row of typed-mjcf, of whichever build (``typed``, ``typed@compiled``)."""
    return case.library == "typed" or case.library.startswith("typed@")


def typed_titles(results: Results) -> list[tuple[str, str]]:
    """(library key, title) of every typed-mjcf build measured, in order."""
    seen: dict[str, str] = {}
    for case in [*results.w1, *results.w2, *results.w3]:
        if is_typed(case):
            seen.setdefault(case.library, case.title)
    return list(seen.items())


def _w1_ratio(results: Results, api: str, naming: str, n: int,
              library: str = "typed") -> float | None:
    case = next((c for c in results.w1 if c.library == library and c.api == api
                 and c.naming == naming), None)
    if case is None:
        return None
    floor = floor_case(results.w1, case)
    a, b = case.sizes.get(n), None if floor is None else floor.sizes.get(n)
    return ratio(None if a is None else a.median(), None if b is None else b.median())


def entry_clock(results: Results) -> str:
    return "CPU time" if results.meta.get("clock", "cpu") == "cpu" else "wall-clock"


def targets(results: Results) -> list[Target]:
    found: list[Target] = []
    sizes = sorted(results.meta.get("w1_sizes", []))
    big = sizes[-2:] if len(sizes) >= 2 else sizes
    for library, title in typed_titles(results) or [("typed", "typed-mjcf")]:
        for api, limit in (("add_<tag>()", W1_TYPED_MAX), ('add("<tag>")', W1_GENERIC_MAX)):
            for naming in ("named", "unnamed"):
                for n in big:
                    r = _w1_ratio(results, api, naming, n, library)
                    if r is None and not results.w1:
                        continue
                    found.append(Target(f"W1 {title} {api} {naming}, N={n:,}: <= {limit}x lxml",
                                        times(r), None if r is None else r <= limit))
    for case in results.w1:
        if is_typed(case) and len(sizes) >= 2:
            g, _ = growth(case, sizes)
            found.append(Target(
                f"W1 growth {case.title} {case.api} {case.naming}: "
                f"t({sizes[-1]:,})/t({sizes[-2]:,}) <= {W1_GROWTH_MAX}",
                "-" if g is None else f"{g:.2f}", None if g is None else g <= W1_GROWTH_MAX))
    k_sizes = sorted(results.meta.get("w3_sizes", []))
    for case in results.w3:
        if is_typed(case) and len(k_sizes) >= 2:
            g, _ = growth(case, k_sizes)
            found.append(Target(
                f"W3 growth {case.title}: t(K={k_sizes[-1]:,})/t(K={k_sizes[-2]:,}) "
                f"<= {W3_GROWTH_MAX} (linear: {k_sizes[-1] / k_sizes[-2]:.1f})",
                "-" if g is None else f"{g:.2f}", None if g is None else g <= W3_GROWTH_MAX))
    for case in results.w2:
        if is_typed(case):
            floor = floor_case(results.w2, case)
            a = next(iter(case.sizes.values()), None)
            b = None if floor is None else next(iter(floor.sizes.values()), None)
            r = ratio(None if a is None else a.median(), None if b is None else b.median())
            limit = W2_TEXT_MAX if case.source.startswith("W1 ") else W2_MAX
            found.append(Target(f"W2 {case.title} {case.source}: <= {limit}x lxml parse+serialise",
                                times(r), None if r is None else r <= limit))
    found += _issue_38_targets(results)
    for entry in results.imports:
        if entry["module"].startswith("typed_mjcf"):
            median = entry.get("median")
            found.append(Target(f"import {entry['module']} < {IMPORT_MAX} s ({entry_clock(results)})",
                                "-" if median is None else f"{median:.3f} s",
                                None if median is None else median < IMPORT_MAX))
    return found


def _issue_38_targets(results: Results) -> list[Target]:
    """W1 named at N = 5,000, W3 at K = 500 and the two bind ratios, for each build."""
    found: list[Target] = []
    for library, title in typed_titles(results):
        if 5000 in results.meta.get("w1_sizes", []):
            r = _w1_ratio(results, "add_<tag>()", "named", 5000, library)
            found.append(Target(f"W1 {title} add_<tag>() named, N=5,000: <= {W1_NAMED_MAX}x lxml",
                                times(r), None if r is None else r <= W1_NAMED_MAX))
        case = next((c for c in results.w3 if c.library == library), None)
        floor = None if case is None else floor_case(results.w3, case)
        if case is not None and floor is not None and 500 in case.sizes:
            a, b = case.sizes[500], floor.sizes.get(500)
            r = ratio(a.median(), None if b is None else b.median())
            found.append(Target(f"W3 {title} K=500: <= {W3_MAX}x lxml", times(r),
                                None if r is None else r <= W3_MAX))
    for row in results.bind:
        limit = {"first_bind": FIRST_BIND_MAX, "from_mjcf_model": FROM_MODEL_MAX}.get(
            row.get("case", ""))
        if limit is not None:
            found.append(Target(f"bind: {row['label']}: <= {limit}x its floor",
                                times(row["ratio"]), row["ratio"] <= limit))
    return found


# ----------------------------------------------------------------------------- whole report


def render(results: Results) -> str:
    meta = results.meta
    out: list[str] = ["# typed-mjcf benchmarks", ""]
    out.append(
        f"{meta.get('mode', '')} run, {meta.get('date', '')}; Python {meta.get('python', '')} "
        f"on {meta.get('platform', '')}, {meta.get('cpus', '?')} CPUs; load average "
        f"{meta.get('load_start', '?')} at start, {meta.get('load_end', '?')} at end.")
    if meta.get("git"):
        out.append(f"Tree: {meta['git']}.")
    versions = meta.get("versions", {})
    if versions:
        out.append("Versions: " + ", ".join(f"{k} {v}" for k, v in versions.items()) + ".")
    missing = meta.get("unavailable", {})
    for key, why in missing.items():
        out.append(f"Left out: {key}: {why}.")
    clock = meta.get("clock", "cpu")
    out.append(
        f"Times are medians, in ms of {CLOCK_WORDS.get(clock, clock)}, over the runs shown "
        "(fewer at large sizes, and fewer when a case exceeds its time budget); (Nx) is the "
        "ratio to raw lxml doing the same work (same naming / same source); growth is "
        "t(largest)/t(next) with the exponent p of t ~ N^p (1.0 = linear). Cases run "
        "round-robin in one process; the JSON has every run's wall-clock and CPU times.")
    out.append("")

    if results.w1:
        sizes = meta["w1_sizes"]
        out += ["## W1 build + export", "",
                (f"N bodies in chains of {meta.get('chain', 10)}, each with a hinge joint, a "
                "capsule geom, a site, a motor and a jointpos sensor; exported with "
                "to_xml_string() (MjSpec: to_xml(), which compiles the spec itself; lxml: "
                "etree.tostring). Unnamed: only joints are named (motors and sensors refer "
                "to them), except dm_control, whose joints are unnamed too and referred to as "
                "elements (its automatic names; the quadratic export)."), "",
                sized_table(results.w1, sizes, "N"), ""]
        for case in results.w1:
            if case.note:
                out.append(f"- {case.label}: {case.note}")
        out += ["", phase_table(results.w1, sizes[-1], "N"), "",
                ("lxml's make builds its tree, so its export is serialisation alone; inside "
                "export, dm_control builds an lxml tree, typed-mjcf formats every value and "
                "writes the text, MjSpec compiles."), "",
                ("CPython's cyclic garbage collector, median ms per run (full collections "
                "in parentheses; wall-clock, through gc.callbacks, with gc.collect() before "
                "each run): a full collection scans every live container object, so its cost "
                "depends on how many the process holds, the model being built included; "
                "'less GC' is the growth with that time taken out."), "",
                collector_table(results.w1, sizes, "N"), ""]
    if results.w2:
        out += ["## W2 parse + export", "",
                ("Parse (typed-mjcf from_path / from_xml_string, dm_control the same, "
                "MjSpec.from_file / from_string, lxml parse with <include> spliced in), then "
                "export as in W1. 'output compiles': MuJoCo compiles the exported text to the "
                "same counts as the source."), "", w2_table(results.w2), ""]
    if results.w3:
        sizes = meta["w3_sizes"]
        out += ["## W3 compose: K attached arms + export", "",
                ("K copies of a 10-body arm model with a default class (10 motors on its "
                "joints), each attached at its own site (typed-mjcf and dm_control: "
                "site.attach(arm); MjSpec: spec.attach(arm, prefix=..., site=site)), then "
                "export. Time includes building the arms. lxml writes typed-mjcf's output "
                "directly."), "", sized_table(results.w3, sizes, "K"), "",
                phase_table(results.w3, sizes[-1], "K"), ""]
    if results.imports:
        out += ["## Import time", "",
                ("A fresh `python -c 'import <module>'` per run, timing only the import, "
                "with bytecode caching as users get it (PYTHONDONTWRITEBYTECODE unset; one "
                "warm-up import first)."), ""]
        def seconds(x: float | None) -> str:
            return "-" if x is None else f"{x:.3f}"

        rows = [[e["module"], seconds(e.get("median_cpu")), seconds(e.get("median_wall")),
                 seconds(min(e["wall"])) if e.get("wall") else "-", str(len(e.get("wall", [])))]
                for e in results.imports]
        out += [table(["module", "median CPU s", "median wall s", "min wall s", "runs"], rows),
                ""]
        if results.importtime:
            rows_all = results.importtime
            total = max((r["cumulative_us"] for r in rows_all), default=0)
            out.append("`python -X importtime -c 'import typed_mjcf'` (one run, "
                       f"{total / 1000:.0f} ms in all, interpreter start-up modules included): "
                       "self time summed by top-level package, and the largest single modules:")
            out.append("")
            packages: dict[str, int] = {}
            for r in rows_all:
                top = r["module"].strip().split(".")[0]
                packages[top] = packages.get(top, 0) + r["self_us"]
            biggest = sorted(packages.items(), key=lambda kv: -kv[1])[:8]
            largest = sorted(rows_all, key=lambda r: -r["self_us"])[:8]
            rows = [[name, f"{us / 1000:.1f}"] for name, us in biggest]
            out += [table(["package", "self ms (sum)"], rows), ""]
            rows = [[r["module"].strip(), f"{r['self_us'] / 1000:.1f}"] for r in largest]
            out += [table(["module", "self ms"], rows), ""]
    if results.memory:
        out += ["## Peak memory, W1 named", "",
                ("A fresh subprocess per library: peak RSS (VmHWM) after import and a tiny "
                "warm-up (baseline), and after building and exporting W1 (the library's main "
                "API); C allocations of libxml2 and MuJoCo included."), ""]
        rows = []
        for m in results.memory:
            if "error" in m:
                rows.append([m["library"], "-", "-", "-", "-", "-", m["error"][:60]])
                continue
            mib = 1024 * 1024
            grown = m["peak_bytes"] - m["baseline_bytes"]
            rows.append([m["library"], f"{m['n']:,}", f"{m['baseline_bytes'] / mib:.0f}",
                         f"{m['after_make_bytes'] / mib:.0f}", f"{m['peak_bytes'] / mib:.0f}",
                         f"{grown / mib:.0f}", f"{grown / m['n'] / 1024:.1f}"])
        out += [table(["library", "N", "baseline MiB", "after make MiB", "peak MiB",
                       "growth MiB", "KiB per body"], rows), ""]
    if results.validity:
        bad = [v for v in results.validity if not v["valid"]]
        out.append("## Output checks")
        out.append("")
        out.append(f"{len(results.validity) - len(bad)} of {len(results.validity)} outputs "
                   "compiled with MuJoCo to the expected model (checked outside the timing).")
        for v in bad:
            out.append(f"- {v['case']}: {v['error']}")
        out.append("")
    found = targets(results)
    out += render_bind(results.bind)
    out += render_variation(results.variation)
    if found:
        out += ["## Targets", ""]
        rows = [["met" if t.met else ("MISSED" if t.met is False else "n/a"), t.text, t.value]
                for t in found]
        out += [table(["", "target", "measured"], rows), ""]
        met = sum(1 for t in found if t.met)
        out.append(f"{met} of {len(found)} targets met.")
    return "\n".join(out).rstrip() + "\n"

