"""What every tests/check_python*.py script does with its checks: records each failure, prints
it, tells whether a call was refused with one line naming what it should, and ends the script
with its verdict."""
import sys

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def refused(call, *fragments):
    """True when call() raises ValueError with a one-line message holding every fragment."""
    try:
        call()
    except ValueError as e:
        message = str(e)
        return "\n" not in message and all(f in message for f in fragments)
    return False


def finish(passed):
    """Exits 1 after the failures' count, or prints `passed`."""
    if failures:
        print(f"{len(failures)} failure(s)")
        sys.exit(1)
    print(passed)
