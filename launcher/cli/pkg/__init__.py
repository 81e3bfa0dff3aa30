"""`launcher pkg list | prefix | share | executables | xml | create`."""
