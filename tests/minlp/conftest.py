import pytest

pytest.importorskip("pyscipopt", reason="the MINLP's tests need PySCIPOpt (the minlp extra)")
