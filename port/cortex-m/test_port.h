/* SPDX-License-Identifier: Apache-2.0 */
/* The port/ SIMD versions against lib/'s references on the target (test_port.c). */
#ifndef SYMLINE_FW_TEST_PORT_H
#define SYMLINE_FW_TEST_PORT_H

void fw_port_checks(void);

#endif /* SYMLINE_FW_TEST_PORT_H */
