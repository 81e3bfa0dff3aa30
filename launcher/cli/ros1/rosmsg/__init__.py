"""`rosmsg show | list | package` and `rossrv show | list | package`, as ROS 1 prints them:
fields with nested types expanded two spaces deeper, `time`/`duration` for the builtin
stamps, and a type given without its package (`rosmsg show Twist`) looked up in every
package, each match under a `[pkg/Type]:` heading. `args.kind` (msg or srv) is the tool's."""
