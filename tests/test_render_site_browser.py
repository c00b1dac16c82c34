"""The gallery site in headless Chromium: every page reachable from the index, no broken link, no console error,
the errata tables sortable.  The expectations come from the errata module and the file tree, not from the pages."""

from __future__ import annotations

import os
from pathlib import Path
from urllib.parse import unquote, urlparse

import pytest

import construct.gallery as gallery
from construct.books.errata import all_errata



@pytest.fixture(scope="module")
def site(tmp_path_factory):
    mp = pytest.MonkeyPatch()
    # two figures of one construction: the first with its player, the second without
    # and a figure whose teaching canvas is mostly paper at its end (the thumbnail shows the drawing)
    mp.setattr(gallery, "gallery_plan", lambda: [("crank", {"parts": 3, "rod_ratio": 4.0}),
                                                 ("crank", {"parts": 3, "rod_ratio": 5.0}),
                                                 ("crank-angle", {"divisions": 4})])
    out = tmp_path_factory.mktemp("site") / "g"
    try:
        gallery.build_gallery(out, workers=1)
    finally:
        mp.undo()
    return out


def _local(url: str) -> Path | None:
    u = urlparse(url)
    return Path(unquote(u.path)) if u.scheme == "file" else None


def test_every_page_is_reachable_and_every_link_resolves(browser, site):  # noqa: F811
    page = browser.new_page()
    errors: list[str] = []
    page.on("console", lambda m: errors.append(f"{page.url}: {m.text}") if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(f"{page.url}: {e}"))
    # a lazy thumbnail still loading when the test moves on is aborted, not missing (files are checked below)
    page.on("requestfailed", lambda r: errors.append(f"{page.url}: failed {r.url} ({r.failure})")
            if "ERR_ABORTED" not in (r.failure or "") else None)
    seen: set[Path] = set()
    todo = [site / "index.html"]
    while todo:
        p = todo.pop()
        if p in seen:
            continue
        seen.add(p)
        page.goto(p.as_uri())
        if p.suffix != ".html":
            continue
        targets = page.evaluate("""() => [...document.querySelectorAll('a[href], img[src]')]
                                   .map(e => e.href || e.src)""")
        assert targets, p
        for t in targets:
            local = _local(t)
            assert local is not None, f"{p}: {t} is not a local file (the site works offline)"
            assert local.is_file(), f"{p}: broken link {t}"
            assert site in local.parents, f"{p}: {t} leaves the gallery"
            if local.suffix in (".html", ".svg"):
                todo.append(local)
    pages = {Path(root) / f for root, _, files in os.walk(site) for f in files if f.endswith(".html")}
    assert pages <= seen, f"not reachable from the index: {sorted(map(str, pages - seen))}"
    assert not errors, errors
    page.close()


def test_errata_pages_hold_every_erratum_sort_and_filter(browser, site):  # noqa: F811
    from construct.books.errata import WRONG
    from construct.render.site import errata_slug

    by_book: dict[str, list] = {}
    for e in all_errata():
        by_book.setdefault(e.source, []).append(e)
    page = browser.new_page()
    for book, rows in by_book.items():
        page.goto((site / errata_slug(book)).as_uri())
        assert page.locator("#all tbody tr").count() == len(rows)
        printed = page.evaluate("() => [...document.querySelectorAll('#all tbody tr')].map(r => r.cells[3].textContent)")
        # the book's order first; a number as printed (a formula is MathML, its text the formula's symbols)
        assert [p for p, e in zip(printed, rows) if e.table != "formula"] == [e.printed for e in rows
                                                                              if e.table != "formula"]
        # the filters work: a class, the wrong ones, a table, and back to all
        assert page.locator("#filters").is_visible()
        page.select_option("#filters select[name=class]", "agrees")
        assert page.locator("#all tbody tr:visible").count() == sum(e.class_ == "agrees" for e in rows)
        assert page.locator("#shown").text_content() == str(sum(e.class_ == "agrees" for e in rows))
        if any(e.class_ in WRONG for e in rows):
            page.select_option("#filters select[name=class]", "*")
            assert page.locator("#all tbody tr:visible").count() == sum(e.class_ in WRONG for e in rows)
        page.select_option("#filters select[name=class]", "")
        table = rows[-1].table
        page.select_option("#filters select[name=table]", index=len(dict.fromkeys(e.table for e in rows)))
        assert page.locator("#all tbody tr:visible").count() == sum(e.table == table for e in rows)
        page.select_option("#filters select[name=table]", "")
        assert page.locator("#all tbody tr:visible").count() == len(rows)
        # the formulas are typeset: MathML laid out by the browser, a fraction taller than a line
        if any(e.table == "formula" and "frac" in e.printed for e in rows):
            heights = page.evaluate("() => [...document.querySelectorAll('#all mfrac')].map(f => f.getBoundingClientRect().height)")
            assert heights and min(heights) > 20
    # Anhang II: sort by the deviation in units, then the other way
    first = next(iter(by_book))
    page.goto((site / errata_slug(first)).as_uri())
    head = page.locator("#all th", has_text="off by")
    head.click()
    got = page.evaluate("() => [...document.querySelectorAll('#all tbody tr')].map(r => r.cells[5].getAttribute('data-v'))")
    units = sorted(abs(e.units) for e in by_book[first] if e.units is not None)
    assert [float(x) for x in got if x][:len(units)] == pytest.approx(units)
    head.click()
    got = page.evaluate("() => [...document.querySelectorAll('#all tbody tr')].map(r => r.cells[5].getAttribute('data-v'))")
    assert [float(x) for x in got if x] == pytest.approx(sorted(units, reverse=True))
    page.close()


def test_errata_pages_without_script_show_the_whole_table_and_no_filters(browser, site):  # noqa: F811
    from construct.render.site import errata_slug

    context = browser.new_context(java_script_enabled=False)
    page = context.new_page()
    rows = [e for e in all_errata() if e.source == "baumann"]
    page.goto((site / errata_slug("baumann")).as_uri())
    assert page.locator("#all tbody tr:visible").count() == len(rows)
    assert not page.locator("#filters").is_visible()
    context.close()


def test_index_shows_a_card_per_figure_with_its_links(browser, site):  # noqa: F811
    page = browser.new_page()
    page.goto((site / "index.html").as_uri())
    cards = page.locator("section.card")
    assert cards.count() == 3
    first = cards.nth(0)
    assert "Kolbenwege aus dem Kurbelkreis" in first.locator("h3").text_content()
    links = {a.text_content(): a.get_attribute("href") for a in first.locator("p.links a").all()}
    assert links["plate"].endswith("/historical/final.svg") and links["step player"].endswith("/teaching/player.html")
    assert links["checks"].endswith("/checks.html")
    assert "step player" not in {a.text_content() for a in cards.nth(1).locator("p.links a").all()}
    # the plate itself opens the plate; the teaching thumbnail opens the player
    assert first.locator("a.plate").get_attribute("href").endswith("/historical/final.svg")
    assert first.locator("a.teach").get_attribute("href").endswith("/teaching/player.html")
    # thumbnails are the figures' own files, loaded
    widths = page.evaluate("() => Promise.all([...document.images].map(i => i.decode().then(() => i.naturalWidth)))")
    assert len(widths) == 5 and all(w > 0 for w in widths)  # the second figure: its plate only
    page.close()


def test_the_teaching_thumbnail_shows_the_figure_not_blank_paper(browser, site):  # noqa: F811
    """The teaching figure's canvas is mostly paper; its thumbnail is cropped to what it draws."""
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page.goto((site / "index.html").as_uri())
    thumb = page.locator("a.teach img").last  # the crank angles' (the crank's fills its canvas anyway)
    thumb.scroll_into_view_if_needed()
    page.wait_for_timeout(300)
    shot = thumb.screenshot()
    import io

    from PIL import Image

    im = Image.open(io.BytesIO(shot)).convert("L")
    w, h = im.size
    inked = [(x, y) for y in range(h) for x in range(w) if im.getpixel((x, y)) < 200]
    xs, ys = [x for x, _ in inked], [y for _, y in inked]
    # the drawing spans most of the thumbnail in one direction at least (the whole canvas left it at a third)
    span = max((max(xs) - min(xs)) / w, (max(ys) - min(ys)) / h)
    assert span > 0.7, span
    page.close()
