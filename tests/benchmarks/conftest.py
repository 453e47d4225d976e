"""Benchmarks: run with `make bench`; results are appended to BENCHMARKS.md."""
