"""Regression testing in geometry: SVG and protocol diffs, gallery verification, the pytest plugin."""
