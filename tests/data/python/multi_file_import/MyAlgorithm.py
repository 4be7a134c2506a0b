# A hand-in of two files (issue 57): MyAlgorithm is the class of the module beside it.
from cleaner import Cleaner as MyAlgorithm
