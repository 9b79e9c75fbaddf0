"""Helpers shared by the book's nodes in this workspace (see sim_time)."""
