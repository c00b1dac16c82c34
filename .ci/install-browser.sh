#!/bin/sh
# Install what tests/test_render_player_browser.py needs: Debian's chromium and the
# Playwright Python client, which drives that system browser (never
# `playwright install`: no browser downloads).
#
# Installing a Debian package needs root (CI runs as root).  Elsewhere, without
# root and without chromium, this says so and carries on: the browser test then
# skips -- except under CI=..., where it fails, so CI never passes without it.
set -eu
if ! command -v chromium >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        export DEBIAN_FRONTEND=noninteractive
        apt-get update
        apt-get install -y --no-install-recommends chromium fonts-dejavu-core
    else
        echo "install-browser: no chromium and no root to install it; the player's browser test will be skipped" >&2
    fi
fi
python -m pip install --quiet "playwright>=1.40"
