"""Launch tests run as launch_testing runs them (`launcher test FILE`, `launch_test FILE`,
`ros2 test FILE`): each run of the file is launched on launcher's launch service, on a graph of
its own, its active tests run while it runs and its post-shutdown tests after."""
