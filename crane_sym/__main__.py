import sys

from crane_sym.cli.main import main

sys.exit(main())
