"""crane_sym: derive, audit and generate code for the dynamics of crane mechanisms."""
__version__ = "0.1.0"
