/* parse.c - the scene language: one function per NFF command (and rt's extensions),
 * found through a table of command names, each reading its numbers through the lexer;
 * the commands that make shapes are in parse_shape.c. Every error names the file and
 * line and says what was expected. The grammar is documented in docs/scene.md.
 * See LICENSE for copyright and licence. */
#include "parse.h"

#include <string.h>

#include "colour.h"
#include "pages.h"
#include "parser.h"
#include "shape.h"

/* The Phong exponent: beyond what the build holds it only gets sharper, so it is held at
 * the largest value (SPD writes 100000, past Q16.16's 32767, for "no highlight"). */
static int read_shine(lexer *lx, real *out)
{
	if (lexer_next(lx)) {
		lexer_push_back(lx);
		if (real_from_text(lx->tok, 0, out) == REAL_TEXT_OUT_OF_RANGE && lx->tok[0] != '-') {
			(void)lexer_next(lx);
			*out = REAL_MAX;
			return 1;
		}
	}
	return lexer_read_nonnegative(lx, "material Shine", out);
}

/* ---- the parser's helpers (parser.h) --------------------------------------------- */

int parser_capacity_error(parser *p, int line, const char *what, const char *limit, long value)
{
	return lexer_fail(&p->lx, line,
		    "too many %s: the limit is %s = %ld (raise it in src/config.h)", what, limit,
		    value);
}

static int same_vec(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* Field by field, not memcmp: a struct's padding bytes are unspecified after assignment. */
static int same_material(const material *a, const material *b)
{
	return same_vec(a->color, b->color) && a->kd == b->kd && a->ks == b->ks &&
	       a->shine == b->shine && a->kt == b->kt && a->ior == b->ior &&
	       same_vec(a->absorb, b->absorb);
}

/* Index of material m, adding it unless an identical one exists; `line` is its entity's. */
static int intern_material(parser *p, const material *m, int line)
{
	scene *s = p->s;
	int i;
	for (i = 0; i < s->material_count; i++)
		if (same_material(&s->materials[i], m))
			return i;
	if (s->material_count == RT_MAX_MATERIALS)
		return parser_capacity_error(p, line, "materials", "RT_MAX_MATERIALS", RT_MAX_MATERIALS),
		       -1;
	s->materials[s->material_count] = *m;
	return s->material_count++;
}

object *parser_new_object(parser *p, unsigned char kind, int line)
{
	scene *s = p->s;
	object *o;
	if (p->material < 0) {
		material white;
		memset(&white, 0, sizeof white);
		white.color = vec_make(REAL_C(1.0), REAL_C(1.0), REAL_C(1.0));
		white.kd = REAL_C(1.0);
		white.ior = REAL_C(1.0);
		p->material = intern_material(p, &white, line);
		if (p->material < 0)
			return NULL;
	}
	if (s->object_count == RT_MAX_OBJECTS) {
		parser_capacity_error(p, line, "objects", "RT_MAX_OBJECTS", RT_MAX_OBJECTS);
		return NULL;
	}
	pages_ahead(s->objects, sizeof s->objects[0], (size_t)s->object_count, 1, RT_MAX_OBJECTS);
	o = &s->objects[s->object_count++];
	memset(o, 0, sizeof *o);
	o->kind = kind;
	o->material = (unsigned short)p->material;
	o->line = line;
	/* Opaque polygons are one-sided (NFF); closed solids, cones, patches and anything
	 * that transmits are seen from both sides. */
	if (!(kind == SHAPE_POLYGON && s->materials[p->material].kt <= REAL_C(0.0)))
		o->flags |= OBJ_TWO_SIDED;
	return o;
}

/* A zero that numbers too small for the type made: one read as 0, or a vector (`v`, not
 * all zero) whose squared length underflows. */
static const char too_small[] = "too small to represent in " REAL_NAME;

const char *parser_zero_word(const parser *p, int line, int nonzero)
{
	return p->lx.tiny_line >= line || nonzero ? too_small : "zero";
}

void parser_warn(parser *p, int line, const char *what)
{
	diag_warning(p->lx.file, line, "%s; skipped", what);
}

/* ---- entities ------------------------------------------------------------------ */

static int parse_view(parser *p)
{
	/* The keywords in their order, each the tail of the name its numbers have in
	 * messages (names[k] + 5): one string serves both. */
	static const char *const names[] = {"view from",  "view at",     "view up",
					    "view angle", "view hither", "view resolution"};
	view *v = &p->s->camera;
	long size;
	int k;
	p->view_line = p->lx.tok_line;
	for (k = 0; k < 6; k++) {
		const char *key = names[k] + 5;
		/* At the end of the file: "expected view from", as a number is named. */
		if (!lexer_next_value(&p->lx, names[k], 1))
			return 0;
		if (strcmp(p->lx.tok, key) != 0)
			return lexer_fail(&p->lx, p->lx.tok_line, "view: expected '%s', got '%s'", key,
				    p->lx.tok);
		/* One call for the three points (from and at are lengths, up is a direction)
		 * and one for the two numbers (hither is a length): 28 bytes less M0 flash
		 * than a case each. */
		if (k < 3) {
			if (!lexer_read_triple(&p->lx, names[k], k < 2,
					 k == 0 ? &v->from : k == 1 ? &v->at : &v->up))
				return 0;
		} else if (k < 5) {
			if (!lexer_read_value(&p->lx, names[k], k == 4, k == 3 ? &v->angle : &v->hither))
				return 0;
			if (k == 3 && !(v->angle > REAL_C(0.0) && v->angle < REAL_C(180.0))) {
				/* Say what the type made of it: 179.99999999 is 180 in float. */
				char held[32];
				real_format(v->angle, 0, held, sizeof held);
				return lexer_fail(&p->lx, p->lx.tok_line,
					    "view angle must be between 0 and 180 degrees, got %s (%s "
					    "in %s)",
					    p->lx.tok, held, REAL_NAME);
			}
		} else {
			if (!lexer_read_count(&p->lx, "resolution width", 1, RT_MAX_SCENE_WIDTH,
					"RT_MAX_SCENE_WIDTH", &size))
				return 0;
			v->width = (int)size;
			if (!lexer_read_count(&p->lx, "resolution height", 1, RT_MAX_SCENE_HEIGHT,
					"RT_MAX_SCENE_HEIGHT", &size))
				return 0;
			v->height = (int)size;
		}
	}
	/* The camera needs a direction and an up that is not along it. */
	{
		vec3 dir = vec_sub(v->at, v->from);
		dir3 side = dir_cross(dir_normalize(dir), dir_normalize(v->up));
		if (!(vec_dot2(dir, dir) > 0))
			return lexer_fail(&p->lx, p->view_line, "view: the distance from 'from' to 'at' is %s",
				    parser_zero_word(p, p->view_line, parser_not_all_zero(dir)));
		if (!(unit_sqrt(dir_dot(side, side)) > UNIT_C(1e-9)))
			return lexer_fail(&p->lx, p->view_line,
				    "view: 'up' is zero or parallel to the view direction");
	}
	return 1;
}

/* Does a number follow on line `line`? Peeks without consuming; an error (reported)
 * returns -1. NFF's optional light colour is told apart this way. */
static int number_follows_on(parser *p, int line)
{
	if (!lexer_next(&p->lx))
		return p->lx.failed ? -1 : (lexer_push_back(&p->lx), 0);
	lexer_push_back(&p->lx);
	if (p->lx.tok_line != line)
		return 0;
	return lexer_is_number(p->lx.tok);
}

static int parse_light(parser *p)
{
	scene *s = p->s;
	int line = p->lx.tok_line;
	light *l;
	if (s->light_count == RT_MAX_LIGHTS)
		return parser_capacity_error(p, line, "lights", "RT_MAX_LIGHTS", RT_MAX_LIGHTS);
	l = &s->lights[s->light_count];
	if (!lexer_read_triple(&p->lx, "light position", 1, &l->position))
		return 0;
	/* The colour is optional: present when a number follows on the same line. */
	p->light_has_color[s->light_count] = number_follows_on(p, line);
	if (p->light_has_color[s->light_count] < 0)
		return 0;
	if (p->light_has_color[s->light_count] &&
	    !lexer_read_triple(&p->lx, "light colour", 0, &l->color))
		return 0;
	if (!p->light_has_color[s->light_count])
		p->unlit_lights++;
	s->light_count++;
	return 1;
}

static int parse_material(parser *p)
{
	lexer *lx = &p->lx;
	int line = lx->tok_line, index;
	material m;
	memset(&m, 0, sizeof m);
	/* Each value is checked as it is read, so a negative one is named at its token. */
	if (!lexer_read_nonnegative(lx, "material colour", &m.color.x) ||
	    !lexer_read_nonnegative(lx, "material colour", &m.color.y) ||
	    !lexer_read_nonnegative(lx, "material colour", &m.color.z) ||
	    !lexer_read_nonnegative(lx, "material Kd", &m.kd) ||
	    !lexer_read_nonnegative(lx, "material Ks", &m.ks) ||
	    !read_shine(lx, &m.shine) ||
	    !lexer_read_nonnegative(lx, "material T", &m.kt) ||
	    !lexer_read_value(lx, "material index of refraction", 0, &m.ior))
		return 0;
	if (m.kt > REAL_C(0.0) && !(m.ior > REAL_C(0.0)))
		return lexer_fail(&p->lx, p->lx.tok_line,
			    "material: T > 0 needs an index of refraction > 0, got %s",
			    p->lx.tok);
	/* ior means nothing for opaque materials (SPD writes 0 or 1): store 1 so they share. */
	if (m.kt <= REAL_C(0.0))
		m.ior = REAL_C(1.0);
	m.color = colour_scene_to_linear(m.color);
	if (RT_COLOUR_PIPELINES && !p->coloured)
		p->coloured = line;
	m.absorb = p->absorb;
	p->absorb = vec_make(REAL_C(0.0), REAL_C(0.0), REAL_C(0.0));
	index = intern_material(p, &m, line);
	if (index < 0)
		return 0;
	p->material = index;
	return 1;
}


/* One absorption coefficient, checked before the look-ahead for more numbers moves the
 * current token on (to the next line, or to end of file). */
static int read_absorption(parser *p, real *out)
{
	if (!lexer_read_nonnegative(&p->lx, "absorption coefficient", out))
		return 0;
	/* Per unit length: a scene scaled up by 2^shift absorbs 2^shift times less per unit. */
	*out = real_ldexp(*out, -p->lx.length_shift);
	return 1;
}

/* `absorb a` (grey) or `absorb ar ag ab` (per channel, on one line). */
static int parse_absorb(parser *p)
{
	int line = p->lx.tok_line, per_channel;
	real a;
	if (!read_absorption(p, &a))
		return 0;
	p->absorb = vec_make(a, a, a);
	per_channel = number_follows_on(p, line);
	if (per_channel < 0)
		return 0;
	return !per_channel ||
	       (read_absorption(p, &p->absorb.y) && read_absorption(p, &p->absorb.z));
}

static int parse_cutoff(parser *p)
{
	scene *s = p->s;
	if (!lexer_read_value(&p->lx, "cutoff weight", 0, &s->cutoff))
		return 0;
	if (!(s->cutoff >= REAL_C(0.0) && s->cutoff < REAL_C(1.0)))
		return lexer_fail(&p->lx, p->lx.tok_line, "cutoff weight must be in [0, 1), got %s",
			    p->lx.tok);
	return 1;
}

/* Lights given without a colour share a total of sqrt(N) (each 1/sqrt(N)), as SPD's own
 * exports to other renderers do. */
static void finish_lights(parser *p)
{
	scene *s = p->s;
	real each;
	int i;
	if (!p->unlit_lights)
		return;
	each = real_div(REAL_C(1.0), real_sqrt(real_from_int(s->light_count)));
	for (i = 0; i < s->light_count; i++)
		if (!p->light_has_color[i])
			s->lights[i].color = vec_make(each, each, each);
}


/* The commands, in the order of enum command (for lexer_keyword). */
static const char command_names[] =
	"v\0b\0l\0f\0s\0p\0pp\0c\0polyhedron\0box\0plane\0ambient\0absorb\0depth\0cutoff\0";
enum command {
	CMD_VIEW, CMD_BACKGROUND, CMD_LIGHT, CMD_MATERIAL, CMD_SPHERE, CMD_POLYGON, CMD_PATCH,
	CMD_CONE, CMD_HEDRON, CMD_BOX, CMD_PLANE, CMD_AMBIENT, CMD_ABSORB, CMD_DEPTH, CMD_CUTOFF,
	CMD_UNKNOWN
};


/* `colours srgb` or `colours classic`: the colour pipeline (colour.h), before the first
 * colour it changes (b, f). */
static int parse_colours(parser *p)
{
	int line = p->lx.tok_line, which;
	if (!lexer_next(&p->lx))
		return lexer_fail(&p->lx, line, "colours: expected srgb or classic");
	which = lexer_keyword("srgb\0classic\0", p->lx.tok);
	if (which > 1)
		return lexer_fail(&p->lx, p->lx.tok_line, "colours: expected srgb or classic, got '%s'",
				  p->lx.tok);
	if (p->coloured)
		return lexer_fail(&p->lx, line, "colours: must come before the first colour "
						"(line %d has one)",
				  p->coloured);
	colour_choose(which ? COLOUR_CLASSIC : COLOUR_SRGB, 1);
	return 1;
}

static int parse_entity(parser *p)
{
	const char *cmd = p->lx.tok;
	long depth;
	switch ((enum command)lexer_keyword(command_names, cmd)) {
	case CMD_VIEW:
		return parse_view(p);
	case CMD_BACKGROUND:
		if (!lexer_read_triple(&p->lx, "background colour", 0, &p->s->background))
			return 0;
		p->s->background = colour_scene_to_linear(p->s->background);
		if (RT_COLOUR_PIPELINES && !p->coloured)
			p->coloured = p->lx.tok_line;
		return 1;
	case CMD_LIGHT:
		return parse_light(p);
	case CMD_MATERIAL:
		return parse_material(p);
	case CMD_SPHERE:
		return parse_sphere(p);
	case CMD_POLYGON:
		return parse_polygon(p, 0);
	case CMD_PATCH:
		if (!RT_SHAPE_PATCH)
			return lexer_fail(&p->lx, p->lx.tok_line,
					  "patches are left out of this build (RT_SHAPE_PATCH)");
		return parse_polygon(p, 1);
	case CMD_CONE:
		if (!RT_SHAPE_CONE)
			return lexer_fail(&p->lx, p->lx.tok_line,
					  "cones are left out of this build (RT_SHAPE_CONE)");
		return parse_cone(p);
	case CMD_HEDRON:
		return parse_hedron(p);
	case CMD_BOX:
		return parse_box(p);
	case CMD_PLANE:
		return parse_plane(p);
	case CMD_AMBIENT:
		return lexer_read_triple(&p->lx, "ambient colour", 0, &p->s->ambient);
	case CMD_ABSORB:
		return parse_absorb(p);
	case CMD_DEPTH:
		if (!lexer_read_count(&p->lx, "depth", 1, RT_MAX_DEPTH, "RT_MAX_DEPTH", &depth))
			return 0;
		p->s->depth = (int)depth;
		return 1;
	case CMD_CUTOFF:
		return parse_cutoff(p);
	default:
		break;
	}
	/* Not in the table: where the build leaves the pipelines out (the MCU), the command
	 * costs nothing, not even its name. */
	if (RT_COLOUR_PIPELINES && strcmp(cmd, "colours") == 0)
		return parse_colours(p);
	/* In a token stream an extra number is read as a command: say so. */
	if (lexer_is_number(cmd))
		return lexer_fail(&p->lx, p->lx.tok_line,
			    "unknown command '%s' (a number: one too many before it?)",
			    cmd);
	return lexer_fail(&p->lx, p->lx.tok_line, "unknown command '%s'", cmd);
}

/* Large: static, so the MCU's small stack never holds it. */
static parser the_parser;

#if RT_READ_BUFFER
/* The block reader of the parse parse_scene_blocks starts (NULL: none), handed on here
 * rather than as a parameter so that parse_scene_at stays as it is where there is no
 * buffer (the MCU, whose flash is full). */
static read_block_fn next_read_block;
#endif

int parse_scene_at(scene *s, const char *file, read_fn read, void *ctx, int length_shift)
{
	parser *p = &the_parser;
	int ok;
	memset(p, 0, sizeof *p);
	scene_init(s, file);
	p->s = s;
	p->material = -1;
	lexer_init(&p->lx, file, read, ctx, length_shift);
#if RT_READ_BUFFER
	if (next_read_block)
		lexer_read_blocks(&p->lx, next_read_block);
#endif
	ok = 1;
	while (ok && lexer_next(&p->lx))
		ok = parse_entity(p);
	if (ok && !p->lx.failed && !p->view_line)
		lexer_fail(&p->lx, p->lx.last_line, "no view: a scene needs a 'v' entity");
	ok = ok && !p->lx.failed;
	if (ok) {
		finish_lights(p);
		s->longest_length = p->lx.longest;
	}
	/* The reader belongs to the caller and may live on its stack: forget it. */
	p->lx.read = NULL;
	p->lx.ctx = NULL;
#if RT_READ_BUFFER
	p->lx.read_block = NULL;
#endif
	return ok;
}

#if RT_READ_BUFFER
int parse_scene_blocks(scene *s, const char *file, read_block_fn read_block, void *ctx,
		       int length_shift)
{
	int ok;
	next_read_block = read_block;
	ok = parse_scene_at(s, file, NULL, ctx, length_shift);
	next_read_block = NULL;
	return ok;
}
#endif

int parse_scene(scene *s, const char *file, read_fn read, void *ctx)
{
	return parse_scene_at(s, file, read, ctx, 0);
}
