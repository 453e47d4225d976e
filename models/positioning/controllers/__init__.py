"""Compensation tables in the formats of machine controllers, one module per controller;
each cites the manual and section of every rule it follows (see
docs/user-guide/positioning.md, "Controller compensation tables", for the rules that could
not be verified)."""

from __future__ import annotations

from models.positioning.controllers import fanuc, heidenhain, isg, mach4, sinumerik, twincat

#: format key → the controller's module (write, lint, build, render, OPTIONS, NAME)
CONTROLLERS = {"sinumerik": sinumerik, "fanuc": fanuc, "heidenhain": heidenhain,
               "twincat": twincat, "isg": isg, "mach4": mach4}

__all__ = ["CONTROLLERS"]
