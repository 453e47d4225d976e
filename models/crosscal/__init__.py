"""Cross-calibration of a polygon and an encoder against each other by the closure
principle (model only; the workbench comes later)."""
