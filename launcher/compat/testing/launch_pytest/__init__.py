"""launch_pytest over launcher's launch service: its pytest plugin (plugin.py), the launch
fixtures (fixture.py) and the launch they run beside, in a thread of its own
(threaded_launch.py); the process tools (tools.py) and the plugin module's helpers
(helpers.py)."""
