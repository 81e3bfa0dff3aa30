"""launch_testing's tools: matching expected output (text.py, output.py) and starting a
process from an active test (process.py)."""
