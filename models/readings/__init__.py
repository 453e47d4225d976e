"""Readings: the sheet a technician types or pastes into, reading files of readings, and
parsing angles."""
