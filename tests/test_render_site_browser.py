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
    mp.setattr(gallery, "gallery_plan", lambda: [("crank", {"parts": 3, "rod_ratio": 4.0}),
                                                 ("crank", {"parts": 3, "rod_ratio": 5.0})])
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


def test_errata_pages_hold_every_erratum_and_sort(browser, site):  # noqa: F811
    from construct.render.site import errata_slug

    by_source: dict[str, list] = {}
    for e in all_errata():
        by_source.setdefault(e.source, []).append(e)
    page = browser.new_page()
    for source, rows in by_source.items():
        page.goto((site / errata_slug(source)).as_uri())
        assert page.locator("tbody tr").count() == len(rows)
        printed = page.evaluate("() => [...document.querySelectorAll('tbody tr')].map(r => r.cells[3].textContent)")
        assert printed == [e.printed for e in rows]  # the book's order first
    # seed 000: sort by the deviation in units, then the other way
    page.goto((site / errata_slug(next(iter(by_source)))).as_uri())
    head = page.locator("th", has_text="deviation")
    head.click()
    got = page.evaluate("() => [...document.querySelectorAll('tbody tr')].map(r => r.cells[5].getAttribute('data-v'))")
    units = sorted(abs(e.units) for e in by_source[next(iter(by_source))] if e.units is not None)
    assert [float(x) for x in got if x][:len(units)] == pytest.approx(units)
    head.click()
    got = page.evaluate("() => [...document.querySelectorAll('tbody tr')].map(r => r.cells[5].getAttribute('data-v'))")
    assert [float(x) for x in got if x] == pytest.approx(sorted(units, reverse=True))
    page.close()


def test_index_shows_a_card_per_figure_with_its_links(browser, site):  # noqa: F811
    page = browser.new_page()
    page.goto((site / "index.html").as_uri())
    cards = page.locator("section.card")
    assert cards.count() == 2
    first = cards.nth(0)
    assert "Kolbenwege aus dem Kurbelkreis" in first.locator("h2").text_content()
    links = {a.text_content(): a.get_attribute("href") for a in first.locator("p.links a").all()}
    assert links["plate"].endswith("/historical/final.svg") and links["player"].endswith("/teaching/player.html")
    assert links["checks"].endswith("/checks.html")
    assert "player" not in {a.text_content() for a in cards.nth(1).locator("p.links a").all()}
    # thumbnails are the figures' own files, loaded
    widths = page.evaluate("() => Promise.all([...document.images].map(i => i.decode().then(() => i.naturalWidth)))")
    assert len(widths) == 3 and all(w > 0 for w in widths)  # the second figure: its plate only
    page.close()
