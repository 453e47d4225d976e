"""The register's refusal: the one exception every register module raises, here so that the
rules the register applies (models/register/clock_rules.py) raise it without importing the
store that applies them (tests/test_import_loops.py). models.register.store re-exports it."""

from __future__ import annotations

__all__ = ["RegisterError"]


class RegisterError(ValueError):
    """The register refused (a number issued before, an unknown certificate, a register of a
    newer version) or cannot be reached; the message says which."""
