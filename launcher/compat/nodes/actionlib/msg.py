"""actionlib.msg: left out of launcher's actionlib (tests/fidelity/left_out.py lists it)."""

raise ImportError("actionlib's own test messages (Test, TestRequest, TwoInts) are not in "
                  "launcher's type store",
                  name=__name__)
