import sys

from crane_sym.cli.start import main

sys.exit(main())
