"""regress/lint/views.py: a layout's letters, found on arrays, are those asked one by one."""

from pathlib import Path

import pytest

from construct.regress.lint import player_data, read_sheet
from construct.regress.lint.views import Views, both_runs, boxes_meet

GALLERY = Path(__file__).resolve().parent.parent / "gallery"


def _one_by_one(views, lay, captions):
    """Every text asked: its box in the layout, whether it meets the layout's box, the views that show it."""
    out = []
    for t in views.sheet.texts:
        if t.kind == "caption" and (views.player or not captions):
            continue
        b = views.text_box(t, lay)
        if not boxes_meet(b, lay.box):
            continue
        runs = both_runs(views.shown(t.chain, t.step, lay.level), lay.runs)
        if runs:
            out.append((t, b, runs))
    return out


@pytest.mark.parametrize("figure", ["crank-parts-18-rod-ratio-5/teaching",
                                    "piston-force/historical"])
@pytest.mark.parametrize("screen", [(1400.0, 900.0), (640.0, 480.0)])
def test_a_layouts_letters_are_those_asked_one_by_one(figure, screen):
    folder = GALLERY / figure
    if not folder.is_dir():
        pytest.skip("no gallery")
    player = folder / "player.html"
    sheet = read_sheet(folder / "final.svg", figure, data=player_data(player) if player.exists() else None)
    views = Views(sheet, screen)
    seen = 0
    for lay in views.layouts:
        for captions in (True, False):
            got = views.letters(lay, captions=captions)
            assert got == _one_by_one(views, lay, captions)
            seen += len(got)
    assert seen > 0


def test_the_steps_of_runs_outside_others_are_counted_off_step_by_step():
    import random

    from construct.regress.lint.views import merge_runs, runs_of, runs_outside, steps_of

    rng = random.Random(7)
    for _ in range(500):
        x = merge_runs((a, a + rng.randint(0, 6)) for a in rng.sample(range(1, 60), rng.randint(0, 6)))
        y = merge_runs((a, a + rng.randint(0, 6)) for a in rng.sample(range(1, 60), rng.randint(0, 6)))
        assert runs_outside(x, y) == runs_of(set(steps_of(x)) - set(steps_of(y)))
