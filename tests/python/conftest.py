"""Counts the bad-input cases the Python tests try: every pytest.raises block that catches the
error it expects. The count is printed at the end of the run ("bad-input cases tried from
Python: N"), the figure docs/errors.md quotes beside cli_bad_input's."""
import pytest

_count = {"cases": 0}
_raises = pytest.raises


class _Counted:
    def __init__(self, context):
        self._context = context

    def __enter__(self):
        return self._context.__enter__()

    def __exit__(self, *exc):
        caught = self._context.__exit__(*exc)
        if caught:
            _count["cases"] += 1
        return caught


def _counting_raises(*args, **kwargs):
    if len(args) > 1 or "func" in kwargs:  # the callable form: no block to count
        _count["cases"] += 1
        return _raises(*args, **kwargs)
    return _Counted(_raises(*args, **kwargs))


pytest.raises = _counting_raises


def pytest_terminal_summary(terminalreporter):
    terminalreporter.write_line(f"bad-input cases tried from Python: {_count['cases']}")
