#!/bin/sh
# Install what tests/test_player_browser.py needs: Debian's chromium and the
# Playwright Python client, which drives that system browser (never
# `playwright install`: no browser downloads).
set -eu
if ! command -v chromium >/dev/null 2>&1; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update
    apt-get install -y --no-install-recommends chromium fonts-dejavu-core
fi
python -m pip install --quiet "playwright>=1.40"
