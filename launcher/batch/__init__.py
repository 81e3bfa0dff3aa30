"""`launcher batch`: launch tests and launch files run over a matrix of arguments, seeds and
repeats, each job on a graph of its own, here (Ray started embedded) or on a Ray cluster.

The batch file (load.py, spec.py) becomes jobs (matrix.py); each job runs on a node under a
job host (host.py, job.py) that a Ray task starts (task.py, cluster.py); the driver
(runner.py) streams their results (results.py) into the reports (table.py, junit_report.py,
csv_report.py, picture.py) and the live progress line (progress.py)."""
