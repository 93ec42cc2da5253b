"""The papers, one package each (installed as ``crane_sym.derivations``): what a
derivation needs from its paper, its model, steps, printed formulas, outputs,
hard cases, scene report and shipped scenes."""
