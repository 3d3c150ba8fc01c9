/* mcu.h - what the microcontroller's platform layer gives its main: buffered standard
 * output and the stack's high-water mark.
 * See LICENSE for copyright and licence. */
#ifndef RT_MCU_H
#define RT_MCU_H

#include <stddef.h>

/* A write_fn for the sinks: buffers bytes for standard output (ctx unused). */
int mcu_stdout_write(void *ctx, const void *data, size_t n);
/* Sends what is buffered; returns 1 on success. */
int mcu_stdout_flush(void);
/* Writes a string to standard error. */
void mcu_stderr(const char *text);
/* Stack bytes used so far at most, from the paint the startup code left. */
size_t mcu_stack_used(void);

#endif
