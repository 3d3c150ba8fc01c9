/* insncount.c - a qemu TCG plugin that counts executed guest instructions: the MCU
 * build's deterministic cost figure (qemu models no cycles). Optionally writes a profile.
 * See LICENSE for copyright and licence.
 *
 * Build: cc -O2 -shared -fPIC -o insncount.so tools/mcu/insncount.c
 * Use:   qemu-system-arm ... -plugin insncount.so[,out=FILE][,profile=FILE] -d plugin
 * Prints "insns: N" through qemu's log (and into FILE with out=). With profile=, also
 * writes one line per translated block: its address, its instruction count and how often
 * it ran (tools/mcu-cost --profile turns that into per-function counts).
 * It declares the few functions of qemu's plugin API (version 1) it uses, so it builds
 * without qemu's headers. */
#include <inttypes.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t qemu_info_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
					      void *ptr, uint64_t imm);
void qemu_plugin_register_vcpu_insn_exec_inline(struct qemu_plugin_insn *insn,
						enum qemu_plugin_op op, void *ptr, uint64_t imm);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb,
				    void *userdata);
void qemu_plugin_outs(const char *string);
#define EXPORT __attribute__((visibility("default")))
EXPORT int qemu_plugin_version = 1;

#define MAX_BLOCKS 65536 /* translated blocks profiled; a small firmware has a few thousand */

static uint64_t insn_count;
static char out_path[512], profile_path[512];

/* Profile: how often each translated block ran. */
static struct {
	uint64_t vaddr, insns, runs;
} blocks[MAX_BLOCKS];
static size_t block_count;

static void tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
	size_t i, n = qemu_plugin_tb_n_insns(tb);
	(void)id;
	/* Exact: one add per executed instruction, so a block left early (a semihosting
	 * call, a fault) counts only what ran. */
	for (i = 0; i < n; i++)
		qemu_plugin_register_vcpu_insn_exec_inline(qemu_plugin_tb_get_insn(tb, i),
							   QEMU_PLUGIN_INLINE_ADD_U64, &insn_count, 1);
	if (profile_path[0] && block_count < MAX_BLOCKS) {
		blocks[block_count].vaddr = qemu_plugin_tb_vaddr(tb);
		blocks[block_count].insns = n;
		qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64,
							 &blocks[block_count].runs, 1);
		block_count++;
	}
}

static void at_exit(qemu_plugin_id_t id, void *p)
{
	char buf[64];
	(void)id;
	(void)p;
	snprintf(buf, sizeof buf, "insns: %" PRIu64 "\n", insn_count);
	qemu_plugin_outs(buf);
	if (out_path[0]) {
		FILE *f = fopen(out_path, "w");
		if (f) {
			fputs(buf, f);
			fclose(f);
		}
	}
	if (profile_path[0]) {
		FILE *f = fopen(profile_path, "w");
		size_t i;
		if (f) {
			for (i = 0; i < block_count; i++)
				fprintf(f, "%" PRIx64 " %" PRIu64 " %" PRIu64 "\n", blocks[i].vaddr,
					blocks[i].insns, blocks[i].runs);
			fclose(f);
		}
	}
}

EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc,
			       char **argv);
EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc,
			       char **argv)
{
	int i;
	(void)info;
	for (i = 0; i < argc; i++) {
		if (!strncmp(argv[i], "out=", 4))
			snprintf(out_path, sizeof out_path, "%s", argv[i] + 4);
		else if (!strncmp(argv[i], "profile=", 8))
			snprintf(profile_path, sizeof profile_path, "%s", argv[i] + 8);
		else {
			fprintf(stderr, "insncount: unknown option %s\n", argv[i]);
			return -1;
		}
	}
	qemu_plugin_register_vcpu_tb_trans_cb(id, tb_trans);
	qemu_plugin_register_atexit_cb(id, at_exit, NULL);
	return 0;
}
