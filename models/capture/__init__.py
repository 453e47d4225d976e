"""Readings captured from the instruments: their protocols parsed from bytes, the
stability gate and the Allan deviation. Pure: no Qt, no pyserial (the connections
live in ``app/capture``)."""
