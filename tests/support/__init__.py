"""Helpers the test modules share, one job per module (the corpus, comparing compiled models,
child-process workers, type checker runs, ...). A ``test_*.py`` module imports helpers from
here or from a helper module of its own folder, never from another ``test_*.py``
(``tests/test_support.py`` checks it)."""
