"""AngleBench application shell: entry points, CLI and main window."""
