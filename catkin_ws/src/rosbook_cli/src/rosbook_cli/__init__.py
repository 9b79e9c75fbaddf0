"""Boundary checks for the project's command-line tools (see checks.py)."""
