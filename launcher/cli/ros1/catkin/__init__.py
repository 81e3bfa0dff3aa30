"""`catkin build | init | clean` (catkin_tools' verbs users type): `build` is catkin_make's
work (packages/catkin.py) with catkin_tools' devel layout of setup files; `init` marks the
workspace; `clean` removes build/ and devel/. catkin_tools' other flags are taken and
unused."""
