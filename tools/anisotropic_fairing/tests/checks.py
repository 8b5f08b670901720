"""The checks of the program's test scripts (resample_test.py, input_meshes_test.py): each prints a line,
and the failed ones are kept for the script's exit status."""

failures = []


def check(ok, what):
    print(('ok      ' if ok else 'FAILED  ') + what)
    if not ok:
        failures.append(what)
    return ok
