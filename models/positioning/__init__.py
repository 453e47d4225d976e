"""Positioning of an axis against a reference: ISO 230-2, VDI/DGQ 3441, compensation."""
