"""launch_testing.pytest: launch_testing's pytest hooks (hooks.py), which collect a launch test
file as one item and run it in the pytest process. launcher's own plugin (compat/pytest_plugin)
is the one pytest loads; these are for plugins that build on launch_testing's."""
