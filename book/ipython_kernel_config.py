# IPython kernel configuration for the book's environment: `make` copies it into
# .venv/etc/ipython/, where every kernel of .venv reads it (the book build, nbval, JupyterLab).
#
# Figures as "retina" PNG: drawn at twice matplotlib's dpi (200 dpi for the default 100) and
# shown at their usual size, so that they stay sharp when a reader zooms or prints the page
# (the PDF takes the same files). gearlib itself sets nothing: importing it changes no state.
c = get_config()  # noqa: F821  (IPython's config loader provides it)
c.InlineBackend.figure_formats = {"retina"}
