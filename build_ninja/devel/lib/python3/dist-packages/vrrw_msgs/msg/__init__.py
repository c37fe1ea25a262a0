from ._Event import *
