"""Negative typing cases: code that must NOT type-check.

Never imported or run. ``tests/typing/test_typecheck.py`` runs mypy and pyright over these
files and compares their errors, line by line, with the trailing markers::

    body.add_geom(tpye="capsule")  # E: mypy[call-arg] pyright[reportCallIssue]

``# E:`` is followed by one ``checker[code, ...]`` group per checker that must report an
error on that line (mypy error codes; pyright rule names). A line without a marker, or a
checker not named in its marker, must get no error at all; a named code that is not
reported and a reported code that is not named both fail the test.
"""
