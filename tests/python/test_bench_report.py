"""``benches/report.py`` keeps the notes written by hand (``benches/notes.md``):
a full report and a partial one (``--only``) both carry them, as they are,
right after the machine, and a partial report keeps every other section."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture()
def report(tmp_path, monkeypatch):
    spec = importlib.util.spec_from_file_location("bench_report", ROOT / "benches" / "report.py")
    mod = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, "bench_report", mod)
    spec.loader.exec_module(mod)
    notes = tmp_path / "notes.md"
    notes.write_text("## Notes between runs (by hand)\n\nA paragraph.\n\n### Sub\n\nMore.\n")
    monkeypatch.setattr(mod, "NOTES", notes)
    monkeypatch.setattr(mod, "OUT", tmp_path / "BENCHMARKS.md")
    monkeypatch.setattr(mod, "SCALING", tmp_path / "no-scaling")
    return mod


def titles(text: str) -> list[str]:
    return [line[3:] for line in text.splitlines() if line.startswith("## ")]


def test_a_full_report_carries_the_notes_after_the_machine(report):
    text = report.write({})
    t = titles(text)
    assert t[:2] == ["Machine", "Notes between runs (by hand)"]
    assert "A paragraph.\n\n### Sub\n\nMore." in text
    assert t[2:] == [s.title for s in report.SECTIONS]


def test_a_partial_report_keeps_the_other_sections_and_the_notes_as_written(report):
    old = report.write({}).replace("A paragraph.", "An old paragraph.")
    old = old.replace("(not measured yet", "(kept text", 1)
    report.OUT.write_text(old)
    report.NOTES.write_text(report.NOTES.read_text().replace("A paragraph.", "A new paragraph."))
    chosen = [report.SECTIONS[-1]]
    text = report.write_only({}, chosen)
    assert titles(text) == titles(old)
    assert "A new paragraph." in text and "An old paragraph." not in text
    assert "(kept text" in text
    assert "(This section alone measured" in text.split("## " + chosen[0].title, 1)[1]
