#!/usr/bin/env python3
"""The JSON Schema of the scene format agrees with the reader.

Usage: schema_check.py SOURCE_DIR

- the schema is a valid draft-07 schema;
- every sample scene (resources/scenes/*.json) and every file of
  tests/data/valid/ is accepted;
- every broken file of tests/data/broken/ whose flaw a schema can express is
  rejected; the few it cannot express (listed below, with the reason) are
  accepted, so this list states exactly where the schema stops.
"""
import glob
import json
import os
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("FAIL: python3-jsonschema is missing (Debian: apt-get install python3-jsonschema); "
             "the scene schema cannot be checked without it")

# Flaws that only the reader or validateScene can see: they need the whole
# scene or the raw text.
SCHEMA_BLIND = {
    "loop-index-out-of-range.json": "the number of vertices of the part is data, not structure",
    "duplicate-key.json": "a JSON parser keeps one of the values before the schema runs",
}

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "..")
    schema_path = os.path.join(source, "resources", "schema", "regio-scene.schema.json")
    schema = load(schema_path)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)

    samples = sorted(glob.glob(os.path.join(source, "resources", "scenes", "*.json")))
    valid = sorted(glob.glob(os.path.join(source, "tests", "data", "valid", "*.json")))
    check(samples, "no sample scenes found in resources/scenes/")
    check(valid, "no files found in tests/data/valid/")
    for path in samples + valid:
        errors = list(validator.iter_errors(load(path)))
        check(not errors, f"{path}: rejected by the schema: " +
              "; ".join(f"/{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in errors[:3]))

    broken_dir = os.path.join(source, "tests", "data", "bad")
    expected = {}
    with open(os.path.join(broken_dir, "format.tsv"), encoding="utf-8") as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            name, stage, location, _message = line.rstrip("\n").split("\t")
            expected[name] = (stage, location)
    check(len(expected) >= 40, f"format.tsv lists only {len(expected)} broken files")
    for name in SCHEMA_BLIND:
        check(name in expected, f"{name} is listed as schema-blind but is not in format.tsv")

    rejected = accepted = 0
    for name, (stage, location) in sorted(expected.items()):
        path = os.path.join(broken_dir, name)
        syntax = location[:1].isdigit()
        if syntax and name not in SCHEMA_BLIND:
            continue  # not JSON at all: the reader's syntax tests cover it
        document = load(path)
        valid_for_schema = validator.is_valid(document)
        if stage == "validation" or name in SCHEMA_BLIND:
            check(valid_for_schema, f"{name}: expected the schema to accept it (its flaw is beyond a schema)")
            accepted += 1
        else:
            check(not valid_for_schema, f"{name}: the schema accepts it, but Regio rejects it at {location}")
            rejected += 1

    print(f"schema: {len(samples)} sample scenes and {len(valid)} valid files accepted; "
          f"{rejected} broken files rejected; {accepted} beyond a schema accepted")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
