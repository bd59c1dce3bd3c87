"""burmester._counts: the one place the Python package decides by the number
of poses. Its table must say what the core does: each capability it offers
for a pose count is one the core accepts for a task of that count, and each
it withholds is one the core refuses (by the pose count, naming it)."""

import math
import subprocess
import sys
from pathlib import Path

import pytest

import burmester
from burmester import _counts as counts
from burmester import taskfile

ROOT = Path(__file__).resolve().parents[2]

# Four poses of the notes' worked example (positions-4-5.md, section 6), as
# in test_cli_pairs.py.
FOUR = [
    (1.049199280691, 2.279426358634, math.radians(45.220037141544)),
    (0.734502065472, 3.198658887874, math.radians(26.633426990744)),
    (-0.378159188147, 3.063048993013, math.radians(21.786789298262)),
    (-1.268710439724, 2.051150142014, math.radians(27.048624103934)),
]


def tasks():
    example = taskfile.example()
    five = taskfile.load(ROOT / "examples" / "five.toml")
    return {
        3: (burmester.Task(list(example.poses)), example.driven_center),
        4: (burmester.Task(FOUR), None),
        5: (five.task, None),
    }


def accepts(call):
    """Whether the core accepts ``call()``; a refusal must be by the pose count."""
    try:
        call()
    except burmester.InvalidInputError as e:
        assert "needs a task of" in str(e), e
        return False
    return True


@pytest.mark.parametrize("n", [3, 4, 5])
def test_the_table_says_what_the_core_offers(n):
    task, c0 = tasks()[n]
    count = counts.of(task)
    assert count is counts.COUNTS[n] and count.poses == n == len(task)
    assert counts.of(task.poses) is count
    assert count.filemon == accepts(lambda: task.filemon(c0 if c0 is not None else (4.0, -1.0)))
    assert count.filemon == accepts(task.pole_circle)
    assert count.curves == accepts(task.coincidence_points)
    assert count.curves == accepts(lambda: task.pair_map(8))
    assert count.burmester_points == accepts(task.burmester_points)
    # Exactly one kind of answer per count.
    assert [count.filemon, count.curves, count.burmester_points].count(True) == 1
    assert count.driven == (n in (3, 4)) and count.circle_plane == (n in (3, 4))
    assert count.design_progress == (n != 5)
    assert count.word == {3: "three", 4: "four", 5: "five"}[n]


@pytest.mark.parametrize("n", [0, 2, 6])
def test_a_count_no_task_has_is_refused(n):
    with pytest.raises(burmester.InvalidInputError, match=f"three to five poses, got {n}"):
        counts.of([(0.0, 0.0, 0.0)] * n)


def test_the_explorers_state_imports_no_matplotlib():
    code = ("import sys, burmester.explorer.state, burmester.explorer, burmester.cli; "
            "print('matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
