"""Readings from the instruments over a serial line or TCP: the link, the instruments'
drivers and the worker thread that reads them (the protocols themselves are parsed by
``models.capture``)."""
