#ifndef VSPH_CLI_CMD_TENSORS_H
#define VSPH_CLI_CMD_TENSORS_H
/** @file cmd_tensors.h @brief `vsph tensors`. */
/** @brief Entry point; returns the process exit status. */
int vsph_cmd_tensors_main(int argc, char **argv);
#endif /* VSPH_CLI_CMD_TENSORS_H */
