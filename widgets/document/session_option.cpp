// OptionSignal's meta-object (AUTOMOC reads the header beside this file).
#include "document/session_option.h"
