#!/usr/bin/env bash
# The ctest fixture faults_samples (tests/CMakeLists.txt): the files of every kind the stages
# write (make_samples, tests/faults/common.sh: packings, checkpoints, normal and tangential
# results of seeds 1 and 2, their average and fit), made once per suite for the fault tests that
# damage copies of them (bit_flips, disk_full, paths), in BIN_DIR/../test-fixtures/faults-samples.
#
#   samples.sh BIN_DIR SOURCE_DIR
bin=$1 root=$2
source "$(dirname "$0")/common.sh"
rm -rf "$samples_fixture"
make_samples "$samples_fixture/s"
touch "$samples_fixture/done"
echo "ok: samples of every file kind in $samples_fixture/s"
