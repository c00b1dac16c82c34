"""Captions in the figure's letters (construct/kernel/letters.py): the book's numbers, symbols and names.

Expectations are what the seeds print (the decimal comma, ω and λ, Gl. (4₁), subscript digits) and the
objects' names of a figure written out here -- never the module's own output.
"""

from __future__ import annotations

import pytest

from construct.kernel.letters import (CAPTION_LIMIT, Reader, book_symbols, displayed, equation, number, subscripts,
                                      tag)


@pytest.mark.parametrize("v, lang, digits, printed", [
    (0.4, "de", 4, "0,4"), (2.0, "de", 4, "2"), (1529.0720493, "de", 5, "1529,1"), (1529.0720493, "en", 5, "1529.1"),
    (0.000125, "de", 4, "0,000125"), (830.0, "en", 4, "830"),
])
def test_numbers_as_the_books_print_them(v, lang, digits, printed):
    assert number(v, lang, digits) == printed


def test_the_books_symbols_replace_their_ascii_stand_ins():
    assert book_symbols("q = F/f (cos w + lam cos 2w)") == "q = F/f (cos ω + λ cos 2ω)"
    assert book_symbols("the sweep, the window, two words") == "the sweep, the window, two words"  # w in words stays
    assert equation("Gl. 4_1 and Gl. (4_1)") == "Gl. (4₁) and Gl. (4₁)"
    assert subscripts("s_0, s_1, p_max") == "s₀, s₁, pmax"


def test_a_shown_caption_is_bounded_and_says_it_was_cut():
    text = "x" * (CAPTION_LIMIT + 50)
    shown = displayed(text)
    assert len(shown) == CAPTION_LIMIT and shown.endswith("…") and displayed("kurz") == "kurz"


def test_a_helper_goes_by_the_last_part_of_its_name():
    assert tag("T4.G.M2") == "M2"
    assert tag("ordD.A", {"A"}) == "a"  # the figure letters a point A already: the helper is written small


def test_the_reader_names_objects_by_the_figures_letters():
    """P3 is lettered 3 in the figure; a compass circle has no letter and goes by its centre."""
    r = Reader({"P3": ("point", "3", None, ()), "D0": ("point", "A", None, ()), "X3": ("point", "3′", None, ()),
                "rod3": ("circle", None, "circle_radius", ("P3", "L"))})
    assert r.text("rod3 meets the stroke line at X3", "en") == "the circle about 3 meets the stroke line at 3′"
    assert r.text("Kreis um P3 durch D0", "de") == "Kreis um 3 durch A"


def test_a_family_of_helpers_is_not_read_as_a_lettered_points_helper():
    """X.c45 is the piston position of the crank point c45 (lettered 45°): X(45°).  u.T1 is the apex T1 of the
    division u, not a helper of the point T1 that the figure letters 720°; U' and its circle U'.k are U′."""
    r = Reader({"c45": ("point", "45°", None, ()), "X.c45": ("point", None, None, ()),
                "T1": ("point", "720°", None, ()), "u.T1": ("point", None, None, ()),
                "U'": ("point", None, None, ()), "U'.k": ("circle", None, "circle_radius", ("U'", "r"))})
    assert r.text("X.c45 und u.T1", "de") == "X(45°) und T1"
    assert r.text("Kreis um U' (U'.k)", "de") == "Kreis um U′ (Kreis um U′)"
    assert r.text("the crank's circle", "en") == "the crank's circle"


def test_one_reader_reads_a_caption_anew_for_each_step_that_writes_it():
    """A reader remembers the words and the captions that name nothing; a caption that names an object is read
    for its step: the step's own helper circle has no letter there, a later step's circle goes by its centre."""
    r = Reader({"P3": ("point", "3", None, ()), "T4.k": ("circle", None, "circle_radius", ("P3", "L"))})
    for _ in range(2):  # (the second round reads what the first has remembered)
        assert r.text("T4.k meets the stroke line", "en", outputs=["T4.k"]) == "meets the stroke line"
        assert r.text("T4.k meets the stroke line", "en", outputs=["P3"]) == "the circle about 3 meets the stroke line"
        assert r.text("the ray meets the vertical", "en", outputs=["T4.k"]) == "the ray meets the vertical"


def test_half_of_a_hyphenated_word_is_never_read_as_a_name():
    """The flywheel rim's mid-plane is a line named "mid" without a letter; its own step's caption said
    "-plane of the wheel" because "mid" in "mid-plane" was read as the unlettered line and dropped."""
    r = Reader({"mid": ("line", None, "given_line", ("O",)), "plane": ("point", "P", None, ())})
    assert r.text("mid-plane of the wheel (radius)", "en", outputs=["mid"]) == "mid-plane of the wheel (radius)"
    assert r.text("mid meets the rim", "en", outputs=["mid"]) == "meets the rim"
