#!/bin/sh
# Install what tests/test_render_tikz.py compiles with: Debian's TeX Live (pdflatex, lualatex; TikZ,
# geometry and Latin Modern -- latex-base, latex-recommended through pictures, luatex; latex-extra for
# the xpatch that tkz-euclide loads, with no recommended packages) and poppler-utils (pdftoppm
# rasterises the compiled page).
#
# Installing a Debian package needs root (CI runs as root).  Elsewhere, without root, this says so and
# carries on: the compiling tests then skip -- except under CI=..., where they fail.
set -eu
if ! command -v pdflatex >/dev/null 2>&1 || ! command -v lualatex >/dev/null 2>&1 \
        || ! command -v pdftoppm >/dev/null 2>&1 || ! kpsewhich xpatch.sty >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        export DEBIAN_FRONTEND=noninteractive
        apt-get update
        apt-get install -y --no-install-recommends texlive-latex-base texlive-pictures texlive-luatex \
            texlive-latex-extra poppler-utils
    else
        echo "install-tex: no TeX Live and no root to install it; the LaTeX tests will be skipped" >&2
    fi
fi
