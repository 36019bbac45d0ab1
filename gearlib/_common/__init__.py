"""Private helpers the methods share; nothing here is part of gearlib's public interface.

* :mod:`.linalg` - exact sparse elimination over rationals, algebraic numbers and gear-ratio
  symbols (the exact and symbolic solvers, synthesis);
* :mod:`.multilinear` - fast factoring of the multilinear polynomials gear trains produce;
* :mod:`.topology` - union-find, coaxial groups and connected components on plain ids;
* :mod:`.parse` - safe reading of the numbers, angles and expressions in mechanism data;
* :mod:`.files` - reading a data file in bounded time and memory (regular files only, no
  duplicate keys, no alias bombs);
* :mod:`.matview` - matrices shown with labelled rows and columns;
* :mod:`.nogc` - pausing Python's cyclic garbage collector while a large structure is built;
* :mod:`.exports` - the lazy export lists every subpackage of gearlib declares.
"""
