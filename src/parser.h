/* parser.h - what the scene parser's two files share: parse.c (the scene's own
 * commands, the table of commands and the pass) and parse_shape.c (the commands that
 * make shapes). Nothing else includes it; parse.h is the parser's interface.
 * See LICENSE for copyright and licence. */
#ifndef RT_PARSER_H
#define RT_PARSER_H

#include "lexer.h"
#include "scene.h"

typedef struct {
	lexer lx;
	scene *s;
	int material;     /* current material index, -1 before the first `f` */
	vec3 absorb;      /* absorption for the next `f` */
	int view_line;    /* line of `v`, 0 if none yet */
	int unlit_lights; /* lights given without a colour */
	int coloured;     /* line of the first colour (b, f) the pipeline decodes; 0: none */
	int light_has_color[RT_MAX_LIGHTS];
} parser;

/* Reported at the line of the entity that does not fit, naming the macro and its value.
 * One copy for its five callers (RT_APART): 48 bytes less M0 flash. */
RT_APART int parser_capacity_error(parser *p, int line, const char *what, const char *limit,
				   long value);

/* A new object slot with the current material (white diffuse before any `f`), for the
 * entity on `line`; NULL after reporting a full scene. It is counted at once: its entity
 * sets it up and cannot fail after. */
object *parser_new_object(parser *p, unsigned char kind, int line);

/* "zero", or why it is zero when it is not exactly: a number read as 0 on or after `line`
 * (where the entity, or the polyhedron's row, starts), or `nonzero`, a vector that is not
 * all zero where the squares of numbers can underflow (parser_not_all_zero). One copy for
 * its three callers (RT_APART). */
RT_APART const char *parser_zero_word(const parser *p, int line, int nonzero);

/* Is v not all zero, where that can mean its squared length underflowed (in fixed point
 * products are exact: never)? */
static int parser_not_all_zero(vec3 v)
{
	return REAL_SQUARES_UNDERFLOW && (v.x != 0 || v.y != 0 || v.z != 0);
}

/* A warning that the entity on `line` is skipped, saying why (`what`). */
void parser_warn(parser *p, int line, const char *what);

/* The shapes' commands (parse_shape.c): each reads its numbers after the command word
 * and sets up its object; 0 after reporting an error. */
int parse_sphere(parser *p);
/* `p n` or `pp n` (patch = 1). Apart (RT_APART): inlined into the entity loop it cost 48
 * bytes more M0 flash. */
RT_APART int parse_polygon(parser *p, int patch);
int parse_cone(parser *p);
int parse_hedron(parser *p);
int parse_box(parser *p);
int parse_plane(parser *p);

#endif
