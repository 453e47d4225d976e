"""Cross-calibration (polygon + encoder) workbench: presenter and view."""
