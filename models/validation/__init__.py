"""Method validation (ISO/IEC 17025 7.2.2): reference cases with known answers.

The rig modules (``rotation``, ``theodolite_rig``, ``polygon_rig``,
``fringe_rig``) simulate each test from first principles — 3-D rotations of
mirror and face normals, sampled signals with a true phase — and import
nothing from the rest of ``models``: they do not share a line of the
equations they check (a test enforces it). The test suite and the
validation report (``anglebench validate``) both use them; ``cases`` holds
the reference cases the report lists.
"""
