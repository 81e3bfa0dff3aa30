"""What more than one test module uses (a test module imports no other test module, nor a
conftest.py: those hold only fixtures and hooks)."""
