#pragma once
// A view that reaches into a panel: the widgets layering check must reject this tree.
#include "document/take_document.h"
#include "panels/gap_list_panel.h"
