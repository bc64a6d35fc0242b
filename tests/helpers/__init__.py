"""Helpers shared by the tests (import as `from tests.helpers.x import …`)."""
