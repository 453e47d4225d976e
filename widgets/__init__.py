"""Qt views and presenters of AngleBench (the numerics live in ``models``)."""
