"""Launch tests, one home for launch_testing's and launch_pytest's machinery on launcher's
launch service (the shims `launch_testing` and `launch_pytest` give it their names).

A test file, read (loader.py): its generate_test_description, the marks the loader and runner
read (markers.py), its actions (actions.py: ReadyToTest, Test, GTest, PyTest) and handlers
(event_handlers.py). A run (worker.py): the description launched on a graph of its own, its
active tests beside it, given what the launch records (records.py; io_handler.py and
proc_info_handler.py over active.py; util.py finds a process), then its post-shutdown
tests; test_runner.py is launch_testing's runner of the runs, launch_test.py its command line
(`launcher test` is cli/test_command.py). The tests' checks and tools: asserts.py, tools/.
Results: test_result.py and junitxml.py (launch_testing's), junit.py (launcher's reports:
`launcher test --junit-xml`, rostest). pytest: pytest_plugin.py (launcher's, a file a process
of its own), pytest_hooks.py (launch_testing's own, in the pytest process); launch_pytest/, its
plugin, fixtures and the launch they run beside. legacy/: launch_testing.legacy's service.
"""
