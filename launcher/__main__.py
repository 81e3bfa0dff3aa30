from launcher.cli.entry import main

raise SystemExit(main())
