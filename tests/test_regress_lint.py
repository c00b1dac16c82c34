"""``construct lint``: legibility findings on small drawings with collisions built in, and clean ones.

The drawings are written here by hand, with the classes the renderer uses
(DESIGN §7), so every expected finding follows from where the test put
things: two labels on one spot, a label on a point, a result line through a
label, a tiny label.  Sizes of letters are checked against the font's own
outlines (matplotlib's TextPath), not against the code's output.
"""

from __future__ import annotations

import json

import pytest

from construct.regress.lint import LintInputError, lint_path, lint_svg
from construct.regress.lint.fonts import text_extents

CSS = """.lb{fill:#000;stroke:none;font-family:'DejaVu Sans', Arial, sans-serif;font-size:12px;text-anchor:middle}
.lb.halo{fill:#fff;stroke:#fff;stroke-width:3.5px}
.pt{fill:#000;stroke:none}
.result{stroke:#000;stroke-width:2;fill:none}
.construction{stroke:#888;stroke-width:0.7;fill:none}
.cap{font-family:'DejaVu Sans';font-size:14px}
.old{opacity:0.45}
.done{opacity:0.13}
.cur>*{stroke:#e8590c;stroke-width:2.6}
.cur>.pt{fill:#e8590c;stroke:#e8590c;stroke-width:3}
.tag{display:none;font-size:10px}
.cur>.tag{display:inline}"""


def svg(body: str, *, width: float = 1400, height: float = 900, css: str = CSS) -> str:
    return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {width:g} {height:g}">'
            f"<style>{css}</style>{body}</svg>")


def label(text: str, x: float, y: float, ident: str, halo: bool = True, cls: str = "lb") -> str:
    h = f'<text class="lb halo" x="{x:g}" y="{y:g}">{text}</text>' if halo else ""
    return h + f'<text class="{cls}" id="{ident}" x="{x:g}" y="{y:g}">{text}</text>'


def point(ident: str, x: float, y: float, r: float = 2.0) -> str:
    return f'<circle class="pt" id="{ident}" cx="{x:g}" cy="{y:g}" r="{r:g}"/>'


def kinds(findings) -> list[str]:
    return sorted(f.kind for f in findings)


def but_fill(findings) -> list:
    """The findings but the canvas's fill (these drawings are a few letters on a large sheet, on purpose)."""
    return [f for f in findings if f.kind != "fill"]


# --------------------------------------------------------------------------- the font's metrics

@pytest.mark.parametrize("text", ["K17", "q7", "ω7′", "Wj"])
def test_text_extents_are_the_glyph_outlines(text):
    from matplotlib.font_manager import FontProperties, findfont
    from matplotlib.textpath import TextPath

    (x0, y0, x1, y1), advance = text_extents(text, "'DejaVu Sans', sans-serif", 12.0)
    ext = TextPath((0, 0), text, size=12.0, prop=FontProperties(fname=findfont("DejaVu Sans"))).get_extents()
    # control points of the outline's quadratic pieces may stand a hair outside the outline itself
    assert x0 == pytest.approx(ext.x0, abs=0.3) and x1 == pytest.approx(ext.x1, abs=0.3)
    assert -y1 == pytest.approx(ext.y0, abs=0.3) and -y0 == pytest.approx(ext.y1, abs=0.3)
    assert x1 <= advance + 1.0


def test_widths_come_from_the_font_not_from_counting_characters():
    # 'i' is a quarter em wide, 'W' a whole one: three of each at the same spacing
    narrow = svg(label("iii", 100, 100, "a") + label("iii", 118, 100, "b"))
    wide = svg(label("WWW", 100, 100, "a") + label("WWW", 130, 100, "b"))
    assert lint_svg(narrow, "narrow.svg") == []
    assert kinds(lint_svg(wide, "wide.svg")) == ["overlap"]


# --------------------------------------------------------------------------- a plate: one view

def test_a_clean_figure_has_no_findings():
    body = (point("s0001-A", 40, 40) + label("A", 52, 36, "s0001-A-label")
            + point("s0002-B", 460, 240) + label("B", 472, 236, "s0002-B-label")
            + '<line class="result" id="s0003-g" x1="40" y1="40" x2="460" y2="240"/>'
            + '<text class="cap" x="24" y="300">Fig. 1. A clean figure</text>')
    assert lint_svg(svg(body, width=500, height=320), "clean.svg") == []


def test_two_labels_on_one_spot_overlap_and_are_named():
    body = label("K6", 300, 300, "s0040-K6-label") + label("K7", 303, 301, "s0041-K7-label")
    (f,) = lint_svg(svg(body), "stack.svg")
    assert f.kind == "overlap" and set(f.labels) == {"K6", "K7"}
    assert set(f.ids) == {"s0040-K6-label", "s0041-K7-label"} and f.figure == "stack.svg" and f.steps == ()


def test_labels_closer_than_their_halos_read_as_one_word():
    # "ω7ω6": the two labels' glyphs do not touch, but their halos do (3.5 px stroke: 1.75 each side)
    (_, _, x1, _), adv = text_extents("ω7", "'DejaVu Sans'", 12.0)
    gap = 2.0  # between the ink of the first and the ink of the second, under two halves of a halo
    x_second = 300 + (x1 - adv / 2) + gap + adv / 2 - text_extents("ω6", "'DejaVu Sans'", 12.0)[0][0]
    body = label("ω7", 300, 300, "a") + label("ω6", x_second, 300, "b")
    assert kinds(lint_svg(svg(body), "tight.svg")) == ["overlap"]
    apart = label("ω7", 300, 300, "a") + label("ω6", x_second + 4.0, 300, "b")
    assert lint_svg(svg(apart), "apart.svg") == []


def test_a_label_on_another_point_but_not_on_its_own():
    body = (point("s0001-A", 300, 300) + label("A", 300, 304, "s0001-A-label")  # on its own point: allowed
            + point("s0002-B", 500, 300) + point("s0003-C", 520, 300) + label("B", 520, 304, "s0002-B-label"))
    found = but_fill(lint_svg(svg(body), "points.svg"))
    assert kinds(found) == ["on-point"]
    assert found[0].ids == ("s0002-B-label", "s0003-C")


def test_a_result_line_through_a_label_strikes_it_and_a_helper_line_does_not():
    lab = label("q4", 300, 300, "s0009-q4-label")
    through = '<line class="result" id="s0010-t" x1="250" y1="296" x2="350" y2="296"/>'
    helper = '<line class="construction" id="s0010-h" x1="250" y1="296" x2="350" y2="296"/>'
    # the label's ink reaches about 2.5 below the baseline, its halo 1.75 more, the line 1 wide each side
    below = '<line class="result" id="s0010-b" x1="250" y1="310" x2="350" y2="310"/>'
    found = but_fill(lint_svg(svg(lab + through), "struck.svg"))
    assert kinds(found) == ["struck"] and found[0].ids == ("s0009-q4-label", "s0010-t")
    assert but_fill(lint_svg(svg(lab + helper), "helper.svg")) == []
    assert but_fill(lint_svg(svg(lab + below), "below.svg")) == []
    # an arc through the label strikes it too (paths are flattened, arcs by their centre and radius)
    arc = '<path class="result" id="s0011-k" d="M200 296A100 100 0 0 1 400 296"/>'  # centre (300, 296), top at y=196
    assert but_fill(lint_svg(svg(lab + arc), "arc.svg")) == []
    # from the bottom (300, 396) to the top (300, 196) in the positive sense (clockwise on the y-down sheet):
    # through the left end (200, 296), not the right one
    arc_left = '<path class="result" id="s0011-k" d="M300 396A100 100 0 0 1 300 196"/>'
    assert kinds(but_fill(lint_svg(svg(label("q4", 200, 300, "x") + arc_left), "left.svg"))) == ["struck"]
    assert but_fill(lint_svg(svg(label("q4", 400, 300, "x") + arc_left), "right.svg")) == []


def test_small_labels_at_the_stated_view_size():
    body = label("A", 300, 300, "s0001-A-label")
    assert lint_svg(svg(body), "a.svg") == []  # 12 px on a 1400-wide view shown at 1400
    # the same drawing twice as large in user units: shown at 1400 px, its 12-unit letters are 6 px
    found = lint_svg(svg(body, width=2800, height=1800), "big.svg")
    assert kinds(found) == ["small-label"] and "6 px" in found[0].message
    # and shown on a larger screen it is legible again
    assert lint_svg(svg(body, width=2800, height=1800), "big.svg", view=(2800, 1800)) == []
    tiny = svg(body, css=CSS.replace("font-size:12px", "font-size:5px"))
    assert kinds(lint_svg(tiny, "tiny.svg")) == ["small-label"]


def test_a_tall_plate_is_measured_at_its_own_width_as_the_browser_shows_it():
    """A plate opened in the browser is shown at the width it asks for (a tall one scrolls), not shrunk into the
    window's height: the 960 × 1280 plate of Tabelle 2 has 12 px letters at 1400 × 900, not 8.4 px."""
    body = label("q₅", 300, 300, "s0001-A-label") + label("+0,907", 300, 1200, "s0002-B-label")
    plate = (f'<svg xmlns="http://www.w3.org/2000/svg" class="plate" width="960" height="1280" viewBox="0 0 960 1280">'
             f"<style>{CSS}</style>{body}</svg>")
    assert [f for f in lint_svg(plate, "tall.svg", view=(1400, 900)) if f.kind == "small-label"] == []
    # wider than the screen it is narrowed to it: 1920 units at 1400 px, letters of 12 units 8.75 px
    wide = plate.replace('width="960" height="1280" viewBox="0 0 960 1280"',
                         'width="1920" height="1280" viewBox="0 0 1920 1280"')
    assert kinds(but_fill(lint_svg(wide, "wide.svg", view=(1400, 900)))) == ["small-label"]


def test_a_label_outside_the_view():
    body = label("Z", 5, 300, "s0001-Z-label")  # the letter's left half is left of x = 0
    found = lint_svg(svg(body), "edge.svg")
    assert kinds(found) == ["outside"] and found[0].labels == ("Z",)


# --------------------------------------------------------------------------- steps and the camera

def steps_svg(*groups: str, **kw) -> str:
    return svg("".join(groups), **kw)


def group(k: int, body: str, cls: str = "step", fade: int | None = None, view: str | None = None) -> str:
    extra = (f' data-fade="{fade}"' if fade else "") + (f' data-view="{view}"' if view else "")
    return f'<g class="{cls}" data-step="{k}"{extra}>{body}</g>'


def test_collisions_are_reported_in_the_steps_that_show_both():
    figure = steps_svg(
        group(1, point("s0001-O", 100, 100)),
        group(2, '<line class="construction" x1="0" y1="600" x2="900" y2="600"/>'),
        group(3, label("K6", 300, 300, "s0003-K6-label")),
        group(4, '<line class="construction" x1="0" y1="700" x2="900" y2="700"/>'),
        group(5, label("K7", 302, 301, "s0005-K7-label")),
        group(6, '<line class="construction" x1="0" y1="800" x2="900" y2="800"/>'))
    found = lint_svg(figure, "steps.svg")
    overlap = [f for f in found if f.kind == "overlap"]
    assert len(overlap) == 1 and overlap[0].steps == ((5, 6),) and overlap[0].views == 2
    # step 1's mark is a dot of radius 2 drawn with a 3-wide ring: 2 * (2 + 1.5) = 7 px (< 12);
    # steps 3 and 5 draw only letters, the lines of 2 and 4 are long
    marks = [f for f in found if f.kind == "small-mark"]
    assert [f.steps for f in marks] == [((1, 1),)] and "7.0 px" in marks[0].message


def test_a_faded_helper_no_longer_collides():
    # step 3's label belongs to a group finished at step 4: from step 5 on it is faded (opacity 0.13)
    figure = steps_svg(
        group(1, label("K6", 300, 300, "s0001-K6-label")),
        group(2, '<line class="construction" x1="0" y1="600" x2="900" y2="600"/>'),
        group(3, label("M1", 302, 301, "s0003-M1-label"), cls="step done", fade=4),
        group(4, '<line class="construction" x1="0" y1="700" x2="900" y2="700"/>'),
        group(5, '<line class="construction" x1="0" y1="800" x2="900" y2="800"/>'),
        group(6, '<line class="construction" x1="0" y1="900" x2="900" y2="900"/>'))
    overlap = [f for f in lint_svg(figure, "fade.svg") if f.kind == "overlap"]
    assert len(overlap) == 1 and overlap[0].steps == ((3, 4),)


def test_name_tags_are_seen_only_while_their_step_is_current():
    tag = '<text class="lb tag" id="s0002-M2-tag" x="301" y="300">M2</text>'
    figure = steps_svg(group(1, label("A", 300, 300, "s0001-A-label")), group(2, tag),
                       group(3, '<line class="construction" x1="0" y1="900" x2="900" y2="900"/>'))
    overlap = [f for f in lint_svg(figure, "tags.svg") if f.kind == "overlap"]
    assert len(overlap) == 1 and overlap[0].steps == ((2, 2),)


def test_a_camera_view_stored_on_a_step_is_read():
    # step 2 is seen through a camera box 140 x 100 (ten times magnified): its 12-unit letter is 120 px,
    # and its tiny mark (a dot of radius 0.3) is 6 units = 60 px; without the camera the mark is 6 px
    dot = '<circle class="pt" id="s0002-P" cx="300" cy="300" r="0.3"/>'
    base = [group(1, label("A", 100, 100, "s0001-A-label")), None,
            group(3, '<line class="construction" x1="0" y1="900" x2="900" y2="900"/>')]
    plain = steps_svg(base[0], group(2, dot), base[2])
    zoomed = steps_svg(base[0], group(2, dot, view="230 250 140 100"), base[2])
    assert [f.steps for f in lint_svg(plain, "plain.svg") if f.kind == "small-mark"] == [((2, 2),)]
    assert [f for f in lint_svg(zoomed, "zoomed.svg") if f.kind == "small-mark"] == []
    # a label cut by the camera's edge in that view is outside it
    cut = steps_svg(base[0], group(2, dot + label("P", 370, 300, "s0002-P-label"), view="230 250 140 100"), base[2])
    out = [f for f in lint_svg(cut, "cut.svg") if f.kind == "outside"]
    assert len(out) == 1 and out[0].steps == ((2, 2),) and out[0].labels == ("P",)


def test_the_camera_may_come_from_the_players_data():
    # a small circle (2.4 units across: 2.4 px on the whole view) seen through a 140 x 100 view in the
    # player's 998 x 630 px window: 15 px.  (A point would not grow: the player holds points at their size.)
    mark = '<circle class="construction" id="s0002-c" cx="300" cy="300" r="1.2"/>'
    figure = steps_svg(group(1, label("A", 100, 100, "s0001-A-label")), group(2, mark),
                       group(3, '<line class="construction" x1="0" y1="900" x2="900" y2="900"/>'))
    assert [f.steps for f in lint_svg(figure, "p.svg") if f.kind == "small-mark"] == [((2, 2),)]
    data = {"n": 3, "steps": [{}, {"v": 0}, {}], "views": [[230, 250, 140, 100]]}
    assert [f for f in lint_svg(figure, "p.svg", data=data) if f.kind == "small-mark"] == []


# --------------------------------------------------------------------------- leaders, captions, the canvas

LEVEL_CSS = CSS + """
.zl1 .lbg>.lb,.zl1 .lbg>.leader,.zl1 .pt{transform:scale(0.5)}
.leader{stroke:#000;stroke-width:0.4px}
.lv1{display:none}.zl1 .lv1{display:inline}.zl1 .m1{display:none}"""


def letter_group(ident: str, x: float, y: float, text: str, dx: float, dy: float, leaders: str = "") -> str:
    """A letter about its point (the renderer's ``lbg`` group), its leaders given as markup."""
    return (f'<g class="lbg" id="{ident}-lb" transform="translate({x:g} {y:g})">{leaders}'
            f'<text class="lb halo" x="{dx:g}" y="{dy:g}">{text}</text>'
            f'<text class="lb" id="{ident}-label" x="{dx:g}" y="{dy:g}">{text}</text></g>')


def test_a_leader_must_start_at_its_point_and_end_at_its_letter():
    # q4 stands 40 units right of its point, its leader from 3 units off the point to 31 (both in the group's units)
    good = '<line class="leader" x1="3" y1="-0.5" x2="31" y2="-3.5"/>'
    body = point("s0001-q4", 300, 300) + letter_group("s0001-q4", 300, 300, "q4", 40, 0, good)
    assert [f for f in lint_svg(svg(body), "good.svg") if f.kind == "leader"] == []
    # the same leader drawn 30 units further out (moved with a letter it no longer reaches from its point)
    moved = '<line class="leader" x1="33" y1="-0.5" x2="61" y2="-3.5"/>'
    found = [f for f in lint_svg(svg(point("s0001-q4", 300, 300) + letter_group("s0001-q4", 300, 300, "q4", 40, 0,
                                                                                 moved)), "moved.svg")
             if f.kind == "leader"]
    assert sorted(f.message for f in found) == ["the leader of label 'q4' (s0001-q4-label) ends away from its letter",
                                                "the leader of label 'q4' (s0001-q4-label) starts away from its point"]


def test_a_zoom_level_that_moves_a_letter_has_a_leader_of_its_own():
    # at zoom level 1 (a camera view twice magnified) the letter moves 30 units up (its level rule); the
    # renderer's leader for the whole figure is hidden there (m1) and one drawn to the moved letter shown (lv1)
    moves = "\n.zl1 #s0001-K6-lb>.lb{transform:scale(var(--ls,var(--zs))) translate(0px,-30px)}"
    whole = '<line class="leader{}" x1="3" y1="-0.5" x2="31" y2="-3.5"/>'
    level = '<line class="leader lv1" x1="2.4" y1="-1.8" x2="29" y2="-23"/>'
    def figure(leaders: str) -> str:
        return steps_svg(group(1, point("s0001-K6", 300, 300) + letter_group("s0001-K6", 300, 300, "K6", 40, 0,
                                                                               leaders)),
                         group(2, '<line class="construction" x1="250" y1="330" x2="350" y2="330"/>'),
                         group(3, '<line class="construction" x1="250" y1="340" x2="350" y2="340"/>'), css=LEVEL_CSS + moves)
    # step 1 shows the whole sheet, steps 2 and 3 a view about the letter magnified 4.8 times: level 1
    data = {"n": 3, "levels": [1.0, 2.0], "steps": [{"v": 0}, {"v": 1}, {"v": 1}],
            "views": [[0, 0, 1400, 1000], [150, 195, 300, 210]]}
    # the old way: the whole figure's leader moved with the letter at the level (its rule moved #id>.leader too)
    rigid = figure(whole.format("")).replace(".lb{transform", ".lb,.zl1 #s0001-K6-lb>.leader{transform")
    assert [f.kind for f in lint_svg(rigid, "rigid.svg", data=data) if f.kind == "leader"] == ["leader"]
    assert [f for f in lint_svg(figure(whole.format(" m1") + level), "own.svg", data=data)
            if f.kind == "leader"] == []


def test_a_leader_to_a_point_the_view_does_not_draw_points_at_nothing():
    # the point is made by a finished group's step (faded away after step 2); its letter, in another step's
    # group, stays: the leader points at nothing in steps 3 and 4
    leader = '<line class="leader" x1="3" y1="-0.5" x2="31" y2="-3.5"/>'
    figure = steps_svg(group(1, '<circle class="pt" id="s0001-P" cx="300" cy="300" r="2"/>', cls="step done", fade=2),
                       group(2, letter_group("s0001-P", 300, 300, "P", 40, 0, leader)),
                       group(3, '<line class="construction" x1="0" y1="600" x2="900" y2="600"/>'),
                       group(4, '<line class="construction" x1="0" y1="700" x2="900" y2="700"/>'),
                       css=CSS.replace(".done{opacity:0.13}", ".done{display:none}"))
    (f,) = [f for f in lint_svg(figure, "hidden.svg") if f.kind == "leader"]
    assert f.steps == ((3, 4),) and f.message.endswith("points at a point the view does not draw")


def captioned(captions: list[str], *bodies: str) -> tuple[str, dict]:
    """A stepped figure (one step group per body) and its player's data with each step's German caption."""
    figure = steps_svg(*(group(k, b) for k, b in enumerate(bodies, start=1)))
    return figure, {"n": len(bodies), "steps": [{"de": c, "en": "", "g": 0} for c in captions], "groups": [""]}


def test_a_caption_names_only_what_its_view_letters():
    tag = '<text class="lb tag" id="s0002-M4-tag" x="512" y="300">M4</text>'  # shown while its step is current
    far = '<line class="construction" x1="0" y1="900" x2="900" y2="900"/>'
    figure, data = captioned(["Kreis um A", "M4 im Schnitt", "Kreis um M5 durch M4", "Gerade c135–M5"],
                             point("s0001-A", 100, 100) + label("A", 112, 96, "s0001-A-label"),
                             point("s0002-M4", 500, 300) + tag, far, far)
    found = {(f.labels, f.steps) for f in lint_svg(figure, "names.svg", data=data) if f.kind == "caption-name"}
    # step 3 names M4, whose tag only its own step shows; step 4 an internal name no figure letters
    assert found == {(("M4",), ((3, 3),)), (("c135",), ((4, 4),))}
    # named where its tag is shown, and a letter before its point is made (the group's goal), are fine
    figure, data = captioned(["Punkt M4 gesucht", "M4 im Schnitt", "Kreis um A"], far, point("s0002-M4", 500, 300) + tag,
                             far)
    assert [f for f in lint_svg(figure, "fine.svg", data=data) if f.kind == "caption-name"] == []


def test_a_drawing_in_a_corner_of_its_canvas_fills_too_little_of_it():
    body = (point("s0001-A", 100, 100) + label("A", 112, 96, "s0001-A-label") + point("s0002-B", 300, 250)
            + '<line class="result" id="s0003-g" x1="100" y1="100" x2="300" y2="250"/>'
            + '<text class="cap" x="24" y="980">Fig. 1. A figure on too large a sheet</text>')
    (f,) = [f for f in lint_svg(svg(body, height=1000), "corner.svg") if f.kind == "fill"]
    # across: 98 … 302 of 1400; down: the letter A's top (85) … 252 of the 967 above the caption
    assert f.message.startswith("the drawing fills 15% of the canvas's width and 17% of its height")
    # the same drawing on a sheet cropped to it with a margin (its caption below): filled
    cropped = svg(body.replace('y="980"', 'y="290"'), width=400, height=300).replace('viewBox="0 0 400 300"',
                                                                                     'viewBox="70 70 270 230"')
    assert [f for f in lint_svg(cropped, "cropped.svg") if f.kind == "fill"] == []


# --------------------------------------------------------------------------- files, folders, the command

def test_a_folder_is_every_final_svg_in_it(tmp_path):
    (tmp_path / "a" / "teaching").mkdir(parents=True)
    (tmp_path / "b").mkdir()
    (tmp_path / "a" / "teaching" / "final.svg").write_text(svg(label("K6", 300, 300, "x") + label("K7", 302, 300, "y")))
    (tmp_path / "b" / "final.svg").write_text(svg(label("A", 300, 300, "z")))
    (tmp_path / "b" / "other.svg").write_text("not read")
    report = lint_path(tmp_path)
    assert report.figures == ["a/teaching/final.svg", "b/final.svg"]
    assert report.totals()["overlap"] == 1 and report.counts()["b/final.svg"] == {}
    assert not report.ok and "a/teaching/final.svg" in report.text()


def test_bad_input_is_a_typed_error(tmp_path):
    with pytest.raises(LintInputError, match="no final.svg"):
        lint_path(tmp_path)
    with pytest.raises(LintInputError, match="no such file"):
        lint_path(tmp_path / "missing")
    (tmp_path / "x.svg").write_text("<html/>")
    with pytest.raises(LintInputError, match="not <svg>"):
        lint_path(tmp_path / "x.svg")


def test_the_command_exits_0_clean_1_findings_2_bad_input(tmp_path, cli):
    # in this process (construct.cli.main, what `python -m construct` runs): the exit codes are main's
    clean, dirty = tmp_path / "clean.svg", tmp_path / "dirty.svg"
    clean.write_text(svg(label("A", 300, 300, "a")))
    dirty.write_text(svg(label("K6", 300, 300, "a") + label("K7", 302, 300, "b")))
    ok = cli("lint", clean)
    assert ok.code == 0 and "no findings" in ok.out
    bad = cli("lint", dirty)
    assert bad.code == 1 and "dirty.svg: figure: overlap: label 'K6' (a) and label 'K7' (b)" in bad.out
    data = json.loads(cli("lint", dirty, "--format", "json").out)
    assert data["totals"]["overlap"] == 1 and data["findings"][0]["labels"] == ["K6", "K7"]
    for args in ((tmp_path / "nothing",), (dirty, "--view", "wide")):
        r = cli("lint", *args)
        assert r.code == 2 and r.out == "" and len(r.err.strip().splitlines()) == 1


def test_the_gallery_check_keeps_the_previous_gallery_when_asked(tmp_path):
    from construct.cli.commands.gallery import IllegibleGallery, _lint

    (tmp_path / "final.svg").write_text(svg(label("K6", 300, 300, "a") + label("K7", 302, 300, "b")))
    _lint(False)(tmp_path)  # reports, does not fail
    with pytest.raises(IllegibleGallery):
        _lint(True)(tmp_path)


# --------------------------------------------------------------------------- real output

def _band():
    """A lettered point A inside a band of result lines 0.008 apart (about 10 px on the canvas): a letter
    with its halo is taller than the gap, so wherever the placer puts it, a result line runs through it."""
    from construct import Builder
    from construct.kernel.rules import left_of

    b = Builder("band", givens={})
    for i in range(101):
        y = -0.4 + 0.008 * i
        b.given_point(f"L{i}", 0.0, y, label="")
        b.given_point(f"R{i}", 1.0, y, label="")
        b.line(f"h{i}", f"L{i}", f"R{i}", role="result")
    b.given_point("T", 0.5, 0.5, label="")
    b.given_point("U", 0.5, -0.5, label="")
    b.line("v", "T", "U", role="construction")
    b.intersect("A", "v", "h50", rule=left_of("L50", "R50"), role="result", labels={"A": "A"})  # never left out
    return b.figure()


@pytest.mark.parametrize("at_once", [0, 1 << 40])
def test_the_result_lines_through_a_letter_are_those_its_box_holds(monkeypatch, at_once):
    """Through the pieces' grid or asked of all pieces at once: the band's lines that strike the letter A are
    those whose height lies in its box grown by half their stroke (the band's lines are level and cross the
    whole letter)."""
    from construct.regress.lint import checks
    from construct.regress.lint.sheet import read_sheet
    from construct.render.scene import build_scene
    from construct.render.svg import Drawing
    from construct.render.styles import STYLES

    monkeypatch.setattr(checks, "_ALL_AT_ONCE", at_once)
    text = Drawing(build_scene(_band()), STYLES["plain"]).layered()
    sheet = read_sheet(text, "band.svg")
    (a,) = [t for t in sheet.texts if t.text == "A" and t.kind == "label"]
    x0, y0, x1, y1 = a.box
    level = [s for s in sheet.strokes if s.ident and "-h" in s.ident]
    assert len(level) == 101 and all(p[1] == p[3] for s in level for p in s.pieces)
    assert all(min(min(p[0], p[2]) for p in s.pieces) < x0 and max(max(p[0], p[2]) for p in s.pieces) > x1
               for s in level)
    expected = {s.ident for s in level if y0 - (s.half - checks.TOUCH) <= s.pieces[0][1] <= y1 + (s.half - checks.TOUCH)}
    found = {f.ids[1] for f in lint_svg(text, "band.svg") if f.kind == "struck" and f.labels == ("A",)}
    assert expected and found == expected


@pytest.mark.parametrize("style", ["plain", "historical"])
def test_the_renderers_output_is_read_and_its_collision_found(tmp_path, style):
    import re

    from construct.regress.lint.sheet import read_sheet
    from construct.render.scene import build_scene
    from construct.render.svg import Drawing
    from construct.render.styles import STYLES

    text = Drawing(build_scene(_band()), STYLES[style]).layered()
    found = lint_svg(text, "band.svg")
    assert any(f.kind == "struck" and f.labels == ("A",) for f in found)
    # the letter lint reads is the one drawn about A: its group's point is A's marker, its box beside it
    (circle,) = re.findall(r'<circle[^>]*id="s\d+-A"[^>]*>', text)
    cx, cy = (float(re.search(rf'{c}="([-\d.]+)"', circle).group(1)) for c in ("cx", "cy"))
    (a,) = [t for t in read_sheet(text, "band.svg").texts if t.text == "A" and t.kind == "label"]
    assert a.anchor == pytest.approx((cx, cy), abs=0.01) and a.owner and a.owner.endswith("-A")
    x0, y0, x1, y1 = a.box
    assert 0 < x1 - x0 < 20 and 0 < y1 - y0 < 20 and abs((x0 + x1) / 2 - cx) < 40 and abs((y0 + y1) / 2 - cy) < 40


def test_construct_golden_checks_legibility_unless_told_not_to(tmp_path):
    from construct.regress.pytest_plugin import GoldenChecker

    fig = _band()  # a collision no placement avoids
    checker = GoldenChecker(goldens=tmp_path / "goldens", default_name="band", update=True)
    with pytest.raises(AssertionError, match="not legible"):
        checker.check(fig)
    assert (tmp_path / "goldens" / "band" / "final.svg").is_file()  # the goldens are written all the same
    GoldenChecker(goldens=tmp_path / "goldens", default_name="band").check(fig, legible=False)


def test_every_mark_of_the_current_step_is_seen_unless_a_ring_of_the_step_holds_it():
    # step 2 marks two points far apart: each is a dot 7 px across, however far apart they are;
    # step 3 marks a dot inside a ring of radius 10 (20 px across): the ring makes it seen
    two = point("s0002-S1", 300, 300) + point("s0002-S2", 400, 300)
    ringed = point("s0003-R", 500, 500) + '<circle class="ring" cx="500" cy="500" r="10"/>'
    css = CSS + ".ring{fill:none;stroke:#e8590c;stroke-width:2}"
    figure = steps_svg(group(1, '<line class="construction" x1="0" y1="900" x2="900" y2="900"/>'),
                       group(2, two), group(3, ringed),
                       group(4, '<line class="construction" x1="0" y1="800" x2="900" y2="800"/>'), css=css)
    marks = [f for f in lint_svg(figure, "marks.svg") if f.kind == "small-mark"]
    assert [f.steps for f in marks] == [((2, 2),)] and marks[0].ids == ("s0002-S1", "s0002-S2")


def test_a_replays_frames_are_one_figure_and_a_collision_in_frame_after_frame_is_one_finding(tmp_path):
    stack = label("K6", 300, 300, "s0001-K6-label") + label("K7", 302, 300, "s0001-K7-label")
    (tmp_path / "steps").mkdir()
    (tmp_path / "final.svg").write_text(svg(label("A", 100, 100, "a")))
    (tmp_path / "steps" / "001.svg").write_text(steps_svg(group(1, stack, cls="step cur")))
    (tmp_path / "steps" / "002.svg").write_text(steps_svg(group(1, stack, cls="step old"),
                                                          group(2, point("s0002-P", 600, 600), cls="step cur")))
    report = lint_path(tmp_path)
    assert report.figures == ["final.svg", "steps/*.svg"]
    overlap = [f for f in report.findings if f.kind == "overlap"]
    assert len(overlap) == 1 and overlap[0].steps == ((1, 2),) and overlap[0].figure == "steps/*.svg"
    # frame 2's current mark is a dot 7 px across
    assert [f.steps for f in report.findings if f.kind == "small-mark"] == [((2, 2),)]


def test_a_plate_layered_by_step_is_one_view():
    # a plate's style sheet keeps the current letters' halo rule but marks no current step: never stepped through
    plate_css = CSS.replace(".cur>*{stroke:#e8590c;stroke-width:2.6}", "").replace(
        ".cur>.pt{fill:#e8590c;stroke:#e8590c;stroke-width:3}", ".cur>.lb.halo{fill:#fff}").replace(
        ".cur>.tag{display:inline}", "")
    figure = steps_svg(group(1, point("s0001-O", 100, 100)), group(2, label("K6", 300, 300, "a")),
                       group(3, label("K7", 302, 300, "b")), css=plate_css)
    found = but_fill(lint_svg(figure, "plate.svg"))
    assert [(f.kind, f.steps, f.views) for f in found] == [("overlap", (), 1)]  # and no current mark to check


def test_the_players_current_points_are_seen_at_once(tmp_path):
    # crank: steps that mark two points far apart get no ring (the ring would span the figure); each point
    # must then be 12 px on the player's screen by itself (its highlight halo), as lint measures it
    from construct.constructions import get
    from construct.render.output import write_replay

    c = get("crank")
    write_replay(c, c.figure(parts=9, rod_ratio=5.0), tmp_path, style="teaching", frames="none")
    report = lint_path(tmp_path / "final.svg")
    assert report.views > 50 and [f.line() for f in report.findings if f.kind == "small-mark"] == []
    # and its name tags (operands of the current step) are placed, not stacked on each other or on points
    assert report.ok, report.text()


def test_the_placer_keeps_a_letters_halo_off_a_thick_result_line():
    # a point on a result line 6 units wide: the letter's box (with its halo) keeps 3 units from the line's axis
    from construct.render.lettering import label_box, place

    for direction in ((0.0, 1.0), (1.0, 0.0), (0.0, -1.0)):
        got = place([("a", "result", 1, (100.0, 100.0), direction, "A")], 12.0, lines=[(0.0, 100.0, 200.0, 100.0)],
                    reach=3.0)
        x, y, _dist, thin = got["a"]
        box = label_box(x, y, "A", 12.0)
        assert not thin and (box[3] <= 97.0 or box[1] >= 103.0)


def test_the_placers_box_holds_an_italic_letters_ink():
    # an italic A leans out of its advance at the foot: the placer's box must hold its outline (matplotlib's
    # TextPath of the same font), or a letter beside a line is placed with its foot on it
    from matplotlib.font_manager import FontProperties, findfont
    from matplotlib.textpath import TextPath

    from construct.render.lettering import text_box

    font = "'DejaVu Serif', serif"
    prop = FontProperties(fname=findfont(FontProperties(family="DejaVu Serif", style="italic")))
    for text in ("A₁", "f", "W"):
        x0, y0, x1, y1 = text_box(0.0, 0.0, text, 12.0, font, True, anchor="start")
        ext = TextPath((0, 0), text, size=12.0, prop=prop).get_extents()
        assert x0 <= ext.x0 + 0.3 and x1 >= ext.x1 - 0.3, (text, (x0, x1), (ext.x0, ext.x1))
