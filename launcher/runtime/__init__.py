"""The event loop: launch context, events, process supervision, output and logs."""
