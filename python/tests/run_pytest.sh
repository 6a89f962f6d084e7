#!/bin/sh
# ctest `python_module`: runs pytest over this folder with the Python that built the module.
# Exits 77 (reported as skipped, with the reason printed) when pytest or NumPy is missing.
#   run_pytest.sh PYTHON TESTS_DIR
set -eu
python="$1" tests="$2"
for module in pytest numpy; do
  if ! "$python" -c "import $module" >/dev/null 2>&1; then
    echo "SKIPPED: Python module '$module' not found (Debian package python3-$module)"
    exit 77
  fi
done
exec "$python" -m pytest -q -p no:cacheprovider "$tests"
