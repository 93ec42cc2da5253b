"""Bounded work for a component file's formulas
(crane_sym.components.formula_limits): the issue's formula bombs end quickly,
in bounded memory, each not_checkable with the bound it broke, and the audit
goes on to the file's other formulas."""
from __future__ import annotations

import json
import re
import resource
import subprocess
import sys
import time
from pathlib import Path

import pytest

from crane_sym.components import formula_limits as limits
from crane_sym.components.formula_limits import Refused, TooLarge, bounded, budget, check_print

ROOT = Path(__file__).parents[1]
EXAMPLES = ROOT / "examples" / "drive_trains"
#: The bombs of the issue and their kin: the LaTeX, the start of the reason.
BOMBS = {
    "tower": (r"p = 9^{9^{9^{9}}}", "too large to check: superscripts nested 3 deep"),
    "number tower": (r"p = 9^{9^{9}}", "too large to check: a number raised to a raised power"),
    "e tower": (r"p = e^{e^{e^{e^{c}}}}", "too large to check: superscripts nested 4 deep"),
    "factorials": (r"p = c!!!!!!!!!!", "too large to check: a factorial of a factorial"),
    "big factorial": (r"p = 1000000!", "too large to check: the factorial 1000000!"),
    "sum": (r"p = \sum_{k=1}^{10^{12}} c", "too large to check: a \\sum of 1000000000000 terms"),
    "product": (r"p = \prod_{k=1}^{10^9} c", "too large to check: a \\prod of 1000000000 terms"),
    "terms": ("p = c" + " + c" * 33000, "too large to check: 132005 characters"),
    "power": (r"p = (m_1+m_2+c)^{100000}", "too large to check: the exponent 100000"),
    "deep": ("p = " + "{" * 30 + "c" + "}" * 30, "too large to check: groups nested 30 deep"),
    "limit": (r"p = \lim_{x \to 0} c", "cannot be checked: a limit"),
    "imaginary": (r"p = \sqrt{-c m_1}", "cannot be checked: it is imaginary"),
    # were "crane-sym: error: ComplexInfinity", exit 2, the file's other formulas unaudited
    "division by zero": (r"p = \frac{c}{m_1 - m_1}", "cannot be checked: it is infinite"),
    "logarithm of 0": (r"p = \log(0) c", "cannot be checked: it is infinite or undefined"),
}
GOOD = r"p = \sqrt{\frac{m_1 + m_2}{m_1 \cdot m_2} \cdot c}"     # paper 000's (6)


def bomb_file(folder: Path, bombs: dict) -> Path:
    source = (EXAMPLES / "travel_braking_000.toml").read_text(encoding="utf-8")
    text = source[:source.index("[[formula]]")]
    for name, tex in [*((k, v[0]) for k, v in bombs.items()), ("(6)", GOOD)]:
        text += (f"[[formula]]\nname = {json.dumps(name)}\nlatex = {json.dumps(tex)}\n"
                 'symbols = { c = "transmission.stiffness", "m_1" = "drive.mass", '
                 '"m_2" = "bridge.mass" }\nquantity = "transmission.frequency"\n\n')
    path = folder / "bombs.toml"
    path.write_text(text, encoding="utf-8")
    return path


pytestmark = pytest.mark.harm("bounds")


@pytest.mark.parametrize("case", [k for k in BOMBS if BOMBS[k][1].startswith("too large")
                                  and k not in ("sum", "product")])
def test_the_text_is_refused_before_parsing(case):
    tex, reason = BOMBS[case]
    start = time.perf_counter()
    with pytest.raises(TooLarge) as caught:
        check_print(tex)
    assert f"{caught.value.prefix}: {caught.value}".startswith(reason)
    assert re.search(r"\(at most \d+|one ! at a time|raised power", str(caught.value))
    assert time.perf_counter() - start < 0.5


def test_the_examples_formulas_pass():
    found = 0
    for path in EXAMPLES.glob("*.toml"):
        for tex in re.findall(r'(?m)^latex = "(.*)"$', path.read_text(encoding="utf-8")):
            check_print(json.loads(f'"{tex}"'))
            found += 1
    assert found >= 3


@pytest.fixture(scope="module")
def bombed(tmp_path_factory) -> tuple[subprocess.CompletedProcess, float]:
    """One file with every bomb and paper 000's (6), audited by `crane-sym audit`
    in a process limited to 2 GiB of address space; the process and its seconds."""
    source = bomb_file(tmp_path_factory.mktemp("bombs"), BOMBS)

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))

    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "crane_sym", "audit", str(source), "-q",
                           "--format", "json"], capture_output=True, text=True, timeout=120,
                          preexec_fn=limit, cwd=ROOT)
    return done, time.perf_counter() - start


def test_the_bombs_end_quickly_in_bounded_memory(bombed):
    """The audit of them all ends in well under a minute, in 2 GiB, exit 0, and
    goes on to the file's good formula."""
    done, took = bombed
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    records = {r["label"]: r for r in json.loads(done.stdout)}
    assert records["(6)"]["verdict"] == "confirmed"           # the audit went on
    assert took < 60, took


@pytest.mark.parametrize("case", list(BOMBS))
def test_each_bomb_is_not_checkable_with_its_bound(case, bombed):
    done, _ = bombed
    record = {r["label"]: r for r in json.loads(done.stdout or "[]")}[case]
    assert record["verdict"] == "not_checkable", record
    assert record["detail"].startswith(BOMBS[case][1]), record["detail"]


def test_a_check_over_its_budget_is_not_checkable(tmp_path, monkeypatch):
    from crane_sym.components.file_audit import audit_file
    from crane_sym.components.component_file import read_component_file
    monkeypatch.setattr(limits, "CHECK_SECONDS", 1.0)
    source = bomb_file(tmp_path, {"slow": (r"p = e^{e^{c}}", "")})
    start = time.perf_counter()
    records = audit_file(read_component_file(source))
    assert time.perf_counter() - start < 20
    assert [r.verdict for r in records] == ["not_checkable", "confirmed"]
    assert records[0].detail == "too large to check: checking it took over 1 s"


def test_budget_stops_a_block_and_restores_the_alarm():
    import signal
    before = signal.getsignal(signal.SIGALRM)
    start = time.perf_counter()
    with pytest.raises(TooLarge, match=r"^spinning took over 0\.2 s$"):
        with budget(0.2, "spinning"):
            while True:
                pass
    assert time.perf_counter() - start < 2
    assert signal.getsignal(signal.SIGALRM) is before
    assert signal.getitimer(signal.ITIMER_REAL)[0] == 0
    with budget(5, "nothing"):
        pass
    assert issubclass(TooLarge, Refused)


def test_a_small_sum_or_product_is_written_out_and_checked():
    import sympy as sp
    k, c = sp.symbols("k c", positive=True)
    assert bounded(sp.Sum(c, (k, 1, 3)) + sp.Product(c, (k, 1, 2))) == 3 * c + c**2
    with pytest.raises(Refused, match=r"^a \\sum whose bounds are not numbers$"):
        bounded(sp.Sum(c, (k, 1, sp.Symbol("n"))))
    with pytest.raises(TooLarge, match=r"^a \\prod of 1001 terms \(at most 1000\)$"):
        bounded(sp.Product(c, (k, 0, 1000)))
