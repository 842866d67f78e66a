#!/bin/sh
# One scene or mutant test of ctest (suite/scene_tests.cmake,
# suite/mutant_tests.cmake): the raw verdict or mutant status its
# combination's `lightcts run` gave it (suite/scene_run_verdicts.py wrote
# VERDICTS/<test>.txt) must be WANT: Pass, or Fail for a test the drivers'
# expected-failures files list (the known mismatch must still be detected),
# or `killed` for a mutant.
#
#   scene_verdict.sh VERDICTS TEST WANT
#
# Exit 0 as wanted; 1 otherwise, or when the run gave the test no verdict;
# 77 (ctest's skip) when the combination, or the scene's feature, is not
# here (its raw verdict is NotSupported).
verdicts=$1
test=$2
want=$3
if [ ! -f "$verdicts/$test.txt" ]; then
  echo "FAIL: the run gave $test no verdict (its log is beside $verdicts)"
  exit 1
fi
cat "$verdicts/$test.txt"
read -r verdict rest < "$verdicts/$test.txt"
[ "$verdict" = "$want" ] && exit 0
[ "$verdict" = NotSupported ] && exit 77
echo "FAIL: $test is $verdict, expected $want"
exit 1
