/* startup.c - what runs before main on the microcontroller: the vector table, .data
 * copied from flash, .bss cleared, the stack painted (to measure its high-water mark),
 * the command line split into argv, and main's status handed back to the host.
 * See LICENSE for copyright and licence. */
#include <stdint.h>

#include "mcu.h"
#include "semihost.h"

int main(int argc, char **argv);

/* From the linker script (sections.ld). */
extern uint32_t __data_load__[], __data_start__[], __data_end__[];
extern uint32_t __bss_start__[], __bss_end__[];
extern uint32_t __stack[];

#define STACK_PAINT 0xA5A5A5A5u /* the word free stack holds until something uses it */
#define MAX_ARGS 16             /* command-line words */

static char command_line[256];
static char *args[MAX_ARGS + 1];

/* Splits the command line at spaces (qemu joins its `arg=` items with one). */
static int split_arguments(void)
{
	int argc = 0;
	char *p = command_line;
	if (!semihost_command_line(command_line, sizeof command_line))
		return 0;
	while (*p && argc < MAX_ARGS) {
		while (*p == ' ')
			*p++ = '\0';
		if (!*p)
			break;
		args[argc++] = p;
		while (*p && *p != ' ')
			p++;
	}
	args[argc] = 0;
	return argc;
}

/* The linker's symbols bound different objects as far as C knows: compared as
 * addresses (integers), not as pointers. */
size_t mcu_stack_used(void)
{
	uintptr_t at = (uintptr_t)__bss_end__, top = (uintptr_t)__stack;
	while (at < top && *(const uint32_t *)at == STACK_PAINT)
		at += sizeof(uint32_t);
	return (size_t)(top - at);
}

void Reset_Handler(void);
void Reset_Handler(void)
{
	const uint32_t *src = __data_load__;
	uintptr_t at, end = (uintptr_t)__data_end__, limit;
	volatile uint32_t here = 0;
	for (at = (uintptr_t)__data_start__; at < end; at += sizeof(uint32_t))
		*(uint32_t *)at = *src++;
	for (at = (uintptr_t)__bss_start__, end = (uintptr_t)__bss_end__; at < end;
	     at += sizeof(uint32_t))
		*(uint32_t *)at = 0;
	/* Paint up to just below this frame (64 bytes spare); main's frames start here. */
	limit = ((uintptr_t)&here & ~(uintptr_t)3) - 64;
	for (at = (uintptr_t)__bss_end__; at < limit; at += sizeof(uint32_t))
		*(uint32_t *)at = STACK_PAINT;
	semihost_exit(main(split_arguments(), args));
}

/* A fault (a bug, or the stack run into .bss) ends the run with a message and status 3,
 * so the host sees it at once instead of a hung emulator. */
void Fault_Handler(void);
void Fault_Handler(void)
{
	static const char message[] = "rt: processor fault\n";
	semihost_write(semihost_open(":tt", SEMIHOST_APPEND), message, sizeof message - 1);
	semihost_exit(3);
}

/* The vector table: the initial stack pointer, then the handlers. A struct, as C forbids
 * storing a data pointer among function pointers. Only the processor reads it. */
typedef void (*handler)(void);
__attribute__((section(".vectors"), used)) static const struct {
	uint32_t *initial_stack;
	handler handlers[15];
} vector_table = {__stack,
		  {
			  Reset_Handler, /* 1: reset */
			  Fault_Handler, /* 2: NMI */
			  Fault_Handler, /* 3: HardFault */
			  Fault_Handler, /* 4: MemManage (v7-M) */
			  Fault_Handler, /* 5: BusFault (v7-M) */
			  Fault_Handler, /* 6: UsageFault (v7-M) */
			  0, 0, 0, 0,
			  Fault_Handler, /* 11: SVCall */
			  0, 0,
			  Fault_Handler, /* 14: PendSV */
			  Fault_Handler, /* 15: SysTick */
		  }};
