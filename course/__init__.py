"""The course kit: ``python -m course.build`` (``make course``) turns the book's exercises into
what a lecturer hands out and grades; ``course/jupyterhub_config.py`` serves a class. See the
book's page for lecturers (``book/lecturers.ipynb``)."""
