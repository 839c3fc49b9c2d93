#include "cmd_report.h"
int vsph_cmd_report_main(int argc, char **argv) { (void)argc; (void)argv; return 0; }
