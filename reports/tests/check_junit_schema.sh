#!/usr/bin/env bash
# Validates junit.xml files against the JUnit XML schema that Jenkins uses
# (reports/tests/junit.xsd, beside this script) with xmllint, and checks that
# every testcase's classname is BACKEND.GROUP: it starts with the backend its
# name ends in (GROUP.SCENE.BACKEND), so a CI page groups the tests per backend.
#
#   check_junit_schema.sh JUNIT_XML...
#
# Exit: 0 every file validates; 1 one does not, or is missing; 2 usage;
# 77 xmllint is not installed (Debian's libxml2-utils; a skip).
set -euo pipefail

if [ $# -lt 1 ]; then
  echo "usage: $0 JUNIT_XML..." >&2
  exit 2
fi
if ! command -v xmllint >/dev/null; then
  echo "xmllint is not installed (apt-get install libxml2-utils): skipped"
  exit 77
fi
schema="$(cd "$(dirname "$0")" && pwd)/junit.xsd"

status=0
for file in "$@"; do
  if [ ! -s "$file" ]; then
    echo "$file: missing or empty" >&2
    status=1
    continue
  fi
  xmllint --noout --schema "$schema" "$file" || status=1
  # Every <testcase classname="C" name="N">: C's first part is N's last.
  pairs=$(xmllint --xpath '//testcase/@classname | //testcase/@name' "$file" 2>/dev/null |
          sed -E 's/^ *(classname|name)="([^"]*)"$/\1 \2/' || true)
  cases=0
  while read -r classname && read -r name; do
    classname=${classname#classname }
    name=${name#name }
    cases=$((cases + 1))
    if [ "${classname%%.*}" != "${name##*.}" ]; then
      echo "$file: testcase '$name' has classname '$classname', not BACKEND.GROUP" >&2
      status=1
    fi
  done <<< "$pairs"
  if [ "$cases" -eq 0 ]; then
    echo "$file: no testcase" >&2
    status=1
  fi
done
exit $status
