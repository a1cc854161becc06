"""stub"""

SYSTEMS = ()
