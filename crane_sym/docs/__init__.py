"""Documents: a derivation as a handout a teacher can use as it is.

The Markdown walkthrough, the runnable notebook, the printable HTML page (of a
paper, and of a drive train of the user's own: ``drive_train``), and what they
share: numbers to the print's digits, long forms with named
quantities, verdicts in words.

May import: everything below it (vocabulary, ``mechanics``, ``audit``,
``codegen``, ``scenes``).
"""
