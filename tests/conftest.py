"""Shared fixtures: a test module names its paper with ``DERIVATION = "<id>"``."""
import pytest

from crane_sym import registry
from crane_sym.audit.verdicts import audit


@pytest.fixture(scope="module")
def derivation(request):
    """The module's derivation, built once per test run (``registry.get``)."""
    return registry.get(request.module.DERIVATION)


@pytest.fixture(scope="module")
def records(derivation):
    """Audit records of the module's derivation by label."""
    return {r.label: r for r in audit(derivation)}
