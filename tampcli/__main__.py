import sys

from tampcli.cli import main

sys.exit(main())
