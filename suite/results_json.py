"""The one way the suite's Python scripts read a lightcts results.json
(docs/results-format.md, "Reading a results.json"): loaded and checked for
the keys lightcts's own reader (results/results_file.h) requires, so a script
never guesses at one. A file that is not a results.json, or lacks a key every
results.json has, raises ResultsFileError naming the file and the key's path.
"""
import json

# The keys every results.json has had since version 1, per record.
RUN_KEYS = ("tests", "backends")
TEST_KEYS = ("name", "backend", "verdict")
BACKEND_KEYS = ("backend", "status")


class ResultsFileError(Exception):
    pass


def _require(path, record, where, key, kind, kind_name):
    """record[key] exists and is a `kind`; `where` is record's JSON path."""
    at = f"{where}.{key}" if where else key
    if key not in record:
        raise ResultsFileError(f"{path}: {at} is missing")
    if not isinstance(record[key], kind):
        raise ResultsFileError(f"{path}: {at} is not {kind_name}")


def _require_records(path, results, array, keys):
    for i, record in enumerate(results[array]):
        where = f"{array}[{i}]"
        if not isinstance(record, dict):
            raise ResultsFileError(f"{path}: {where} is not an object")
        for key in keys:
            _require(path, record, where, key, str, "a string")


def load(path):
    """The results.json at `path` as a dict, checked."""
    try:
        with open(path) as f:
            results = json.load(f)
    except OSError as e:
        raise ResultsFileError(f"{path}: cannot be read ({e.strerror})")
    except ValueError as e:
        raise ResultsFileError(f"{path}: not JSON: {e}")
    if not isinstance(results, dict) or results.get("format") != "lightcts-results":
        raise ResultsFileError(f'{path}: not a lightcts results.json (no "format": "lightcts-results")')
    for key in RUN_KEYS:
        _require(path, results, "", key, list, "an array")
    _require_records(path, results, "tests", TEST_KEYS)
    _require_records(path, results, "backends", BACKEND_KEYS)
    return results
