// InputError is header-only; this unit keeps the core library non-empty before other files exist.
#include "errors.h"
