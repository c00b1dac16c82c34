"""The plates after the books: letters, scales, closed outlines and the line hierarchy the originals show.

Expectations from the texts (seed 001: "Im Punkte J ... zwischen J und C negativ", Baumann's Fig. 26
"Tangentialdruckdiagramm ABCD", "Ausgleichende MM", the abscissae α1, α2; Fig. 566's two diagrams) and
from the analytic formulas, not from the plates' own output.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET


from construct.constructions import analytic
from construct.constructions import get
from construct.render.output import plate_caption, printed_caption, scene_for
from construct.render.styles import STYLES
from construct.render.svg import render_svg


SVG = "{http://www.w3.org/2000/svg}"


def _plate_svg(name: str, **params) -> str:
    c = get(name)
    fig = c.figure(**params)
    return render_svg(scene_for(c, fig, plate=True), style=STYLES["historical"], caption=printed_caption(c, fig, 1))


def _texts(svg: str) -> list[str]:
    """The letters of a plate as a reader sees them (an index set in a smaller run below the line read on)."""
    root = ET.fromstring(svg.encode("utf-8"))
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text")
            if "lb" in (t.get("class") or "").split() and "halo" not in (t.get("class") or "")]


def _furniture(name: str, **params):
    c = get(name)
    fig = c.figure(**params)
    return fig, c.plate(fig)


def test_indicator_diagram_is_one_closed_outline_at_result_weight():
    fig, plate = _furniture("indicator-diagram")
    R = fig.replay
    heavy = [(tuple(s["a"]), tuple(s["b"])) for s in plate["furniture"] if s["kind"] == "stroke" and s["look"] == "heavy"]
    # the two curves run from the cut-off to the end of the stroke and from the start of compression to it
    exp = [tuple(p) for p in R["expansion"].curve_points()]
    comp = [tuple(p) for p in R["compression"].curve_points()]
    edges = heavy + [(exp[0], exp[-1]), (comp[0], comp[-1])]
    degree: dict[tuple, int] = {}
    for a, b in edges:
        for p in (a, b):
            key = (round(p[0], 9), round(p[1], 9))
            degree[key] = degree.get(key, 0) + 1
    assert len(edges) == 6 and all(d == 2 for d in degree.values()), degree  # a closed loop of six pieces
    assert {plate["looks"]["expansion"], plate["looks"]["compression"]} == {"heavy"}
    # admission at P + P0 = 8 at absolute, back pressure at P0 = 0.15 at (Baumann's numbers), in the drawn scale
    u = R.givens["pressure_unit"]
    assert math.isclose(R["A0"][1] / u, 7.85 + 0.15, rel_tol=1e-12) and math.isclose(R["B0"][1] / u, 0.15, rel_tol=1e-12)


def test_indicator_plate_letters_with_subscripts_and_a_pressure_scale():
    texts = _texts(_plate_svg("indicator-diagram"))
    assert {"s₁", "s₂", "A₁", "C₂"} <= set(texts) and not {"s1", "s2", "A1", "C2"} & set(texts)
    assert "at" in texts and {"0", "4", "8"} <= set(texts)  # the scale from the zero line to P + P0 = 8 at


def test_piston_force_plate_letters_scale_and_line_hierarchy():
    svg = _plate_svg("piston-force")
    texts = set(_texts(svg))
    assert {"O", "C", "J", "kg", "P = F·pü", "Pb"} <= texts
    # seed 001's p_ü and P_b: the index below the line, smaller (no font has a subscript b or ü)
    root = ET.fromstring(svg.encode("utf-8"))
    low = {s.text: s for t in root.iter(f"{SVG}text") if "halo" not in t.get("class", "") for s in t.iter(f"{SVG}tspan")
           if float(s.get("dy", "0")) > 0}
    assert set(low) == {"ü", "b"} and all("font-size" in s.get("style", "") for s in low.values())
    assert "10000" in texts and "0" in texts  # P = F p at admission: 1529 cm² x 7 at = 10 700 kg
    fig, plate = _furniture("piston-force")
    looks = plate["looks"]
    assert looks["forcea"] == looks["mass"] == "heavy" and looks["fbase"] == "thin"
    # C is the end of the force line, below the base line (the force is negative there: "zwischen J und C negativ")
    n = fig.params["parts"]
    assert fig.replay[f"K{n}"][1] < fig.replay[f"F{n}"][1]


def test_the_low_pressure_plate_says_it_shows_the_high_pressure_diagram():
    c = get("piston-force")
    de, en = plate_caption(c, c.figure(weight=990.0), 13)
    assert "Dampfdiagramm der Hochdruckseite" in de and "high-pressure side's steam diagram" in en


def test_tangential_plate_has_baumanns_letters_and_keeps_the_crossings_clear():
    svg = _plate_svg("tangential-pressure", parts=18)
    texts = _texts(svg)
    assert {"A", "B", "D", "α₁", "α₂"} <= set(texts) and texts.count("M") >= 2
    fig, plate = _furniture("tangential-pressure", parts=18)
    assert plate["looks"]["A1"] == plate["looks"]["A2"] == "unlettered"
    base_y = fig.replay["U0"][1]
    mean_y = fig.replay["M0"][1]
    for item in plate["furniture"]:
        if item["kind"] == "lettering" and item["text"].startswith("α"):
            assert item["at"][1] < base_y < mean_y  # lettered below the base line, away from the crossing


def test_two_cranks_plate_no_line_runs_across_the_gap_and_the_reference_circle_is_lighter():
    c = get("two-cranks")
    fig = c.figure(parts=12)
    sc = scene_for(c, fig, plate=True)
    R = fig.replay
    r = R["O"].distance(R["D1"])
    gap = (R["O"][0] + 1.25 * r, R["O'"][0] - 1.25 * r)
    for m in sc.marks:
        if m.kind == "segment":
            x0, _, x1, _ = m.geom
            assert not (min(x0, x1) < gap[0] and max(x0, x1) > gap[1]), m.name
    for it in sc.furniture:
        if type(it).__name__ == "Stroke":
            assert not (min(it.a[0], it.b[0]) < gap[0] and max(it.a[0], it.b[0]) > gap[1]), it
    looks = {m.name: m.look for m in sc.marks}
    assert looks["crank"] == "medium" and looks["wave"] == "heavy"


def test_stroke_fraction_plate_draws_q_as_ordinates_with_their_values():
    fig, plate = _furniture("inertia-stroke-fractions")
    g = fig.replay.givens
    r, L, u = g["r"], g["rod_ratio"] * g["r"], g["pressure_unit"]
    heavy = [s for s in plate["furniture"] if s["kind"] == "stroke" and s["look"] == "heavy"]
    assert len(heavy) == 11
    for j, s in enumerate(heavy):
        # Tabelle 2: q at j/10 of the stroke, the crank angle by Gl. (h), q by Gl. (4₁)
        w = analytic.crank_angle_from_path(2.0 * r * j / 10, r, L)
        q = analytic.inertia_two_term(w, r / L, g["pressure_ratio"])
        assert math.isclose((s["b"][1] - s["a"][1]) / u, q, abs_tol=1e-6), (j, q)
    values = [t["text"] for t in plate["furniture"] if t["kind"] == "lettering" and t["text"][:1] in "+−"]
    assert values[0] == "+1,200" and values[-1] == "−0,800"  # 1 + r/L and -(1 - r/L) at the dead centres


def test_stroke_fraction_plate_fills_its_sheet():
    c = get("inertia-stroke-fractions")
    fig = c.figure()
    sc = scene_for(c, fig, plate=True)
    x0, y0, x1, y1 = sc.bbox
    r = fig.replay.givens["r"]
    # the sheet holds the semicircle and the q diagram under it: no empty band of several crank radii
    # (the proportional angle at SO = L = 5 r below the centre made it 60 % empty)
    assert (y1 - y0) < 3.6 * r and (x1 - x0) > 2.0 * r


def test_two_sided_piston_force_plate_is_a_landscape_sheet_legible_at_1400_by_1000():
    """Stacked in portrait, the four diagrams came out at 7.8 px letters and the scale's 0 sat on the
    base line.  Laid out as a book sets a cover-side and a crank-side diagram: side by side, no diagram over
    another, every ordinate as long as the construction made it, the letters at 9 px or more."""
    from construct.regress.lint import lint_svg
    from construct.render.scene import extreme_points

    c = get("piston-force")
    fig = c.figure(parts=18, revolution=True)
    scene = scene_for(c, fig, plate=True)
    svg = render_svg(scene, style=STYLES["historical"], caption=printed_caption(c, fig, 1))
    assert [f.line() for f in lint_svg(svg, view=(1400, 1000))] == []
    x0, y0, x1, y1 = scene.bbox
    assert x1 - x0 > y1 - y0  # landscape

    def box(pattern):
        pts = [p for m in scene.marks if re.fullmatch(pattern, m.name) for p in extreme_points(m)]
        return min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts)

    boxes = {"cover": box(r"ind\.(steam|backline|[ER]\d+)"), "forward": box(r"fbase|F\d+|K\d+|M\d+|force[abc]|mass"),
             "crank": box(r"crk\.(steam|backline|[ER]r\d+)"), "return": box(r"rbase|rF\d+|rK\d+|rM\d+|rforce[abc]|rmass")}
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            A, B = boxes[a], boxes[b]
            assert A[2] < B[0] or B[2] < A[0] or A[3] < B[1] or B[3] < A[1], f"{a} and {b} overlap"
    # the return stroke beside the forward stroke, on one base level; the cover side above its forward stroke
    fb = next(m for m in scene.marks if m.name == "fbase").geom
    rb = next(m for m in scene.marks if m.name == "rbase").geom
    assert abs(fb[1] - rb[1]) < 1e-9 and min(rb[0], rb[2]) > max(fb[0], fb[2])
    assert boxes["cover"][1] > boxes["forward"][3] and boxes["crank"][1] > boxes["return"][3]
    # a diagram moves as a whole: every piston force keeps its height over its base line (the construction's)
    at = {m.name: m.geom for m in scene.marks if m.kind == "point"}
    for k in range(19):
        for p in ("", "r"):
            assert math.isclose(at[f"{p}K{k}"][1] - at[f"{p}F{k}"][1],
                                fig.replay[f"{p}K{k}"][1] - fig.replay[f"{p}F{k}"][1], abs_tol=1e-12)


def test_a_plate_carries_its_whole_caption_and_the_legend_of_its_letters(tmp_path):
    # the plate prints the German caption with the givens three lines hold; the desc keeps both languages whole
    # and what J, C, O and P_b stand for (seed 001: "Im Punkte J ... wird die Kolbenkraft Null")
    import json

    from construct.render.output import write_outputs

    c = get("piston-force")
    fig = c.figure(weight=990.0)
    write_outputs(tmp_path, c, fig, STYLES["historical"], fig_number=16, outputs=(), protocol=False)
    svg = (tmp_path / "final.svg").read_text(encoding="utf-8")
    desc = json.loads(ET.fromstring(svg.encode("utf-8")).find(f"{SVG}desc").text)
    printed = " ".join("".join(t.itertext()) for t in ET.fromstring(svg.encode("utf-8")).iter(f"{SVG}text")
                       if "cap" in t.get("class", ""))
    whole_de, whole_en = plate_caption(c, fig, 16)
    assert desc["caption"] == {"de": whole_de, "en": whole_en}
    assert "Halbkreis in 18 Teilen" in whole_de and "Halbkreis in 18 Teilen" not in printed  # cut on the plate
    assert printed.startswith("Fig. 16. Kolbenüberdrucklinie") and "piston" not in printed.lower()
    assert desc["legend"]["J"]["de"].startswith("Druckwechsel") and set(desc["legend"]) >= {"O", "C", "J", "P_b"}


def _elements(svg: str, tag: str, cls: str) -> list:
    return [e for e in ET.fromstring(svg.encode("utf-8")).iter(f"{SVG}{tag}") if cls in (e.get("class") or "").split()]


def _xs(d: str) -> list[float]:
    return [float(x) for x in re.findall(r"[ML](-?[\d.]+)", d)]


def test_flywheel_plate_is_baumanns_half_section_lettered_and_hatched():
    # Fig. 28: b1 at the rim, b = b1 r1/r between, b2 = 6 b1 at the hub; hub and rim in section, the disc hatched up
    # to the rim (it is counted to r1, "zu viel gerechnet", but drawn to where the rim begins); centre lines
    svg = _plate_svg("flywheel-rim")
    assert {"b₁", "b", "b₂", "Nabe", "Kranz", "Armscheibe"} <= set(_texts(svg))
    hatch = {re.sub(r"^s\d+-", "", e.get("id")): e.get("d") for e in _elements(svg, "path", "hatch")}
    assert set(hatch) == {"section-hatch", "hubsection-hatch", "rimsection-hatch"}
    rim_inner = min(_xs(next(e.get("d") for e in _elements(svg, "path", "area") if e.get("id").endswith("-rimsection"))))
    assert max(_xs(hatch["section-hatch"])) <= rim_inner + 0.5
    for name in ("axis", "mid"):
        assert "centre" in next(e for e in ET.fromstring(svg.encode("utf-8")).iter()
                                if (e.get("id") or "").endswith(f"-{name}")).get("class").split()


def test_four_stroke_plate_marks_the_dead_centres_and_carries_a_pressure_scale():
    # Abb. 1058 (the Diesel's; Abb. 1056 is the explosion engine's p-V diagram alone): over two revolutions the
    # strokes change at 180°, 360°, 540°; the over-pressure read in at
    texts = set(_texts(_plate_svg("four-stroke", engine="diesel")))
    assert {"0°", "180°", "360°", "540°", "720°", "at", "0", "5", "10", "15", "20"} <= texts
    assert {"Ansaugen", "Verdichten", "Arbeiten", "Auspuffen"} <= texts


def test_indicator_plate_letters_what_its_caption_names():
    assert {"P", "P₀", "s₀", "s₃"} <= set(_texts(_plate_svg("indicator-diagram")))


def test_the_inertia_plate_sets_l_infinite_upright_and_its_scale_in_at():
    svg = _plate_svg("inertia-curve", rod_ratio=4.0)
    (inf,) = [t for t in _elements(svg, "text", "fur-text") if "".join(t.itertext()) == "L = ∞"]
    assert "rotate" not in (inf.get("transform") or "")  # turned along the line the ∞ read as an 8
    assert "1 at" in _texts(svg)


def test_the_crank_plate_has_one_dot_per_division_on_the_stroke():
    # seed 001: each division point's piston position (finite rod, 1' ...) is the one dot on the stroke line; the
    # infinite rod's foot is where its ordinate crosses the line
    svg = _plate_svg("crank", parts=18)
    dots = [e for e in _elements(svg, "circle", "pt") if "hidden" not in e.get("class").split()]
    y_axis = next(float(e.get("cy")) for e in dots if e.get("id").endswith("-O"))
    on_axis = {round(float(e.get("cx")), 1) for e in dots if abs(float(e.get("cy")) - y_axis) < 0.01}
    assert len(on_axis) == 18 + 2  # X0 ... X18 (X0, X18 the dead centres) and O
    assert not [e for e in dots if re.search(r"-Y\d+$", e.get("id"))]


def test_the_compound_plate_hatches_its_plus_and_minus_areas_apart_and_ties_nd_hd_to_their_curves():
    svg = _plate_svg("tangential-pressure", parts=18, revolution=True, machine="compound")
    slopes = set()
    for e in _elements(svg, "path", "hatch"):
        nums = [float(v) for v in re.findall(r"-?[\d.]+", e.get("d"))][:4]
        slopes.add("vertical" if abs(nums[0] - nums[2]) < 0.01 else "slanted")
    assert slopes == {"vertical", "slanted"}  # the work taken up and the work given back
    texts = set(_texts(svg))
    assert {"ND", "HD", "at"} <= texts and len(_elements(svg, "path", "leader") + _elements(svg, "line", "leader")) >= 2


def test_the_two_sided_force_plate_sets_kg_over_its_scale_and_says_why_the_crank_side_hangs():
    svg = _plate_svg("piston-force", parts=18, revolution=True)
    at = {"".join(t.itertext()): float(t.get("y")) for t in _elements(svg, "text", "fur-text")}
    assert at["kg"] < at["10000"]  # over the scale, as in Abb. 1055 (y down)
    assert "Kurbelseite, nach unten aufgetragen" in at and "Deckelseite" in at


def test_a_shifted_item_and_its_runs_are_those_of_the_rules_they_replace():
    """plate.shifted (its item's field names found once a class) maps the same points as asking the dataclass's fields
    at every item did, for every kind of furniture; subscript_runs without an index in the text (one run, no pattern
    asked) is the pattern's answer (fails when a field is left out or the fast runs differ, the empty text's too)."""
    from dataclasses import fields, replace

    from construct.render.plate import (AngleArc, Dimension, Dot, Lettering, ScaleBar, Sign, Stroke, shifted,
                                        subscript_runs)

    def shifted_by_fields(item, sx):
        changes = {}
        for f in fields(item):
            v = getattr(item, f.name)
            if isinstance(v, tuple) and len(v) == 2 and all(isinstance(c, (int, float)) for c in v):
                changes[f.name] = (sx(v[0]), v[1])
        return replace(item, **changes) if changes else item

    items = [Dimension((0.0, 1.0), (2.0, 1.0), "s", -0.3, (1.0, 0.5)), AngleArc((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), 0.4,
             "ω", (0.2, 0.3)), Stroke((0.5, 0.0), (1.5, 2.0), "heavy"), ScaleBar((3.0, 0.0), (3.0, 1.0), "1 at"),
             Lettering((1.0, 2.0), "P_b", to=(1.5, 1.0)), Sign((2.0, 2.0), "+"), Dot((4.0, 4.0))]
    for it in items * 2:  # (the second time: the names found once)
        got, want = shifted(it, lambda x: 2 * x + 1), shifted_by_fields(it, lambda x: 2 * x + 1)
        assert got == want and got != it

    def runs_by_pattern(text):
        out, pos = [], 0
        for m in re.finditer(r"_(\{[^}]*\}|[^\W_])", text):
            if m.start() > pos:
                out.append((text[pos:m.start()], False))
            out.append((m.group(1).strip("{}"), True))
            pos = m.end()
        if pos < len(text) or not out:
            out.append((text[pos:], False))
        return out

    for text in ["", "q₀", "+1,234", "1 at", "P_b", "F·p_ü", "B_{max} t", "_", "a_", "x__y", "L = 3,5 r"]:
        assert subscript_runs(text) == runs_by_pattern(text), text
