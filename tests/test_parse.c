/* test_parse.c - the scene parser, in process: every NFF entity and extension, odd but
 * valid input, and malformed input with its exact message and line.
 * See LICENSE for copyright and licence. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "diag.h"
#include "load.h"
#include "parse.h"
#include "realtext.h"
#include "test.h"

#define FILE_NAME "t.nff"

/* A valid view, lines 1-7; the first entity after it is on line 8. */
#define VIEW_WITH(from, at, up, angle, res)                                                 \
	"v\nfrom " from "\nat " at "\nup " up "\nangle " angle "\nhither 1\nresolution " res \
	"\n"
#define VIEW VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "45", "32 24")

/* Tolerance for values that pass through one or two roundings of `real`. These scenes are
 * read by parse_scene, at scale 1 in every type: in Q16.16 a value read is within half an
 * LSB, and one computed from it (a normalised vector, an sRGB decode) within one more. */
#define EPS TOL3(1e-6, 1e-12, 1.5 * LSB)

/* Sizes in messages follow config.h, which a build may override. */
#define STR RT_STRINGIFY

/* ---- harness: a string reader and a message sink --------------------------------- */

typedef struct {
	const char *text;
	size_t length, next;
} source;

static int read_source(void *ctx)
{
	source *src = ctx;
	return src->next < src->length ? (unsigned char)src->text[src->next++] : -1;
}

static char messages[4096];
static int message_count;

static void capture(void *ctx, const char *message)
{
	size_t used = strlen(messages), n = strlen(message);
	(void)ctx;
	message_count++;
	if (used + n < sizeof messages)
		memcpy(messages + used, message, n + 1);
}

/* Several MB: static, never on the stack. */
static scene sc;

#if RT_READ_BUFFER
/* The block reader's view of a source: at most `chunk` bytes a call, so that blocks end
 * anywhere, inside tokens, spaces and line ends alike. */
typedef struct {
	source src;
	long chunk;
} chunked_source;

static long read_chunks(void *ctx, unsigned char *to, long max)
{
	chunked_source *c = ctx;
	long n = 0;
	while (n < max && n < c->chunk && c->src.next < c->src.length)
		to[n++] = (unsigned char)c->src.text[c->src.next++];
	return n;
}

/* What a parse gave, for comparing the two readers: its numbers by a hash of what the
 * scene holds of them. */
typedef struct {
	unsigned long values;
	int ok, message_count, object_count, light_count, lines[8];
	char messages[sizeof messages];
} parse_outcome;

/* Mixes x into the hash h: its value as a double and the rest of it (long double's last
 * bits), byte by byte. */
static void mix_real(unsigned long *h, real x)
{
	double parts[2];
	const unsigned char *b = (const unsigned char *)parts;
	size_t i;
	parts[0] = (double)x;
	parts[1] = (double)(x - (real)parts[0]);
	for (i = 0; i < sizeof parts; i++)
		*h = (*h ^ b[i]) * 16777619ul;
}

static void mix_vec(unsigned long *h, vec3 v)
{
	mix_real(h, v.x);
	mix_real(h, v.y);
	mix_real(h, v.z);
}

/* A hash of the numbers a parse of sc read: the view, lights, materials, vertices and
 * spheres. */
static unsigned long scene_values(void)
{
	unsigned long h = 2166136261ul;
	int i;
	mix_vec(&h, sc.camera.from);
	mix_vec(&h, sc.camera.at);
	mix_vec(&h, sc.background);
	for (i = 0; i < sc.light_count; i++)
		mix_vec(&h, sc.lights[i].position);
	for (i = 0; i < sc.material_count; i++) {
		mix_vec(&h, sc.materials[i].color);
		mix_real(&h, sc.materials[i].kd);
		mix_real(&h, sc.materials[i].shine);
	}
	for (i = 0; i < sc.vertex_count; i++)
		mix_vec(&h, sc.vertices[i]);
	for (i = 0; i < sc.object_count; i++)
		if (sc.objects[i].kind == SHAPE_SPHERE) {
			mix_vec(&h, sc.objects[i].u.sphere.center);
			mix_real(&h, sc.objects[i].u.sphere.radius);
		}
	return h;
}

static void outcome_of(int ok, parse_outcome *o)
{
	int i;
	o->ok = ok;
	o->values = ok ? scene_values() : 0;
	o->message_count = message_count;
	memset(o->messages, 0, sizeof o->messages);
	memcpy(o->messages, messages, strlen(messages));
	o->object_count = ok ? sc.object_count : 0;
	o->light_count = ok ? sc.light_count : 0;
	for (i = 0; i < 8; i++)
		o->lines[i] = ok && i < sc.object_count ? sc.objects[i].line : 0;
}
#endif

/* Parses `length` bytes (NULs included) with messages captured, not printed. Files are
 * read a block at a time (load.c), and the lexer takes most tokens straight from the
 * block: every case is read that way too, in blocks of 1, 2, 5 and 4096 bytes, and must
 * give the same result, messages and objects' lines as byte by byte. */
static int parse_bytes(const char *text, size_t length)
{
	source src;
	int ok;
#if RT_READ_BUFFER
	static const long chunks[] = {1, 2, 5, RT_READ_BUFFER};
	static parse_outcome by_blocks, by_bytes;
	int c;
	for (c = 0; c < (int)(sizeof chunks / sizeof chunks[0]); c++) {
		chunked_source blocks;
		blocks.src.text = text;
		blocks.src.length = length;
		blocks.src.next = 0;
		blocks.chunk = chunks[c];
		messages[0] = '\0';
		message_count = 0;
		diag_set_sink(capture, NULL);
		ok = parse_scene_blocks(&sc, FILE_NAME, read_chunks, &blocks, 0);
		diag_set_sink(NULL, NULL);
		outcome_of(ok, c == 0 ? &by_blocks : &by_bytes);
		if (c > 0)
			CHECK(memcmp(&by_blocks, &by_bytes, sizeof by_blocks) == 0);
	}
#endif
	src.text = text;
	src.length = length;
	src.next = 0;
	messages[0] = '\0';
	message_count = 0;
	diag_set_sink(capture, NULL);
	ok = parse_scene(&sc, FILE_NAME, read_source, &src);
	diag_set_sink(NULL, NULL);
#if RT_READ_BUFFER
	outcome_of(ok, &by_bytes);
	if (!CHECK(memcmp(&by_blocks, &by_bytes, sizeof by_blocks) == 0))
		printf("    read by blocks: %d, %s    byte by byte: %d, %s", by_blocks.ok,
		       by_blocks.messages, by_bytes.ok, by_bytes.messages);
#endif
	return ok;
}

/* Literals only: sizeof keeps embedded NUL bytes. */
#define PARSE(text) parse_bytes(text, sizeof text - 1)

/* Parses and expects exactly one message `rt: t.nff:LINE: [warning: ]...FRAGMENT...\n`;
 * `at` is the caller's line so a failure points at the case, not here. */
static void expect_message(const char *text, size_t length, int warning, int line,
			   const char *fragment, int at)
{
	char prefix[64];
	size_t n;
	int ok = parse_bytes(text, length), good = 1;
	snprintf(prefix, sizeof prefix, "rt: " FILE_NAME ":%d: %s", line,
		 warning ? "warning: " : "");
	n = strlen(messages);
	/* A warning still parses; an error does not. */
	good &= test_check_int(ok, warning, __FILE__, at, "parse_scene result");
	good &= test_check_int(message_count, 1, __FILE__, at, "number of messages");
	good &= test_check(strncmp(messages, prefix, strlen(prefix)) == 0, __FILE__, at, prefix);
	good &= test_check(strstr(messages, fragment) != NULL, __FILE__, at, fragment);
	good &= test_check(n > 0 && strchr(messages, '\n') == messages + n - 1, __FILE__, at,
			   "one line ending in a newline");
	if (!good)
		printf("    the message was: %s", messages);
}

#define EXPECT_ERROR(text, line, fragment) \
	expect_message(text, sizeof text - 1, 0, line, fragment, __LINE__)
#define EXPECT_WARNING(text, line, fragment) \
	expect_message(text, sizeof text - 1, 1, line, fragment, __LINE__)

/* Parses and expects success with no message at all. */
static void expect_ok(const char *text, size_t length, int at)
{
	int good = test_check_int(parse_bytes(text, length), 1, __FILE__, at, "parse_scene result");
	good &= test_check_int(message_count, 0, __FILE__, at, "number of messages");
	if (!good)
		printf("    the messages were: %s", messages);
}

#define EXPECT_OK(text) expect_ok(text, sizeof text - 1, __LINE__)

static void check_vec(vec3 v, double x, double y, double z, double tol, int at)
{
	test_check_near(test_double(v.x), x, tol, __FILE__, at, "x");
	test_check_near(test_double(v.y), y, tol, __FILE__, at, "y");
	test_check_near(test_double(v.z), z, tol, __FILE__, at, "z");
}

#define CHECK_VEC(v, x, y, z) check_vec(v, x, y, z, EPS, __LINE__)

/* A number past the type's range, and a radius whose square is. */
#if defined(RT_REAL_LONG_DOUBLE)
#define OVERFLOWING "1e99999"
#define TOO_LARGE_RADIUS "1e2500"
#elif defined(RT_REAL_FLOAT)
#define OVERFLOWING "1e999"
#define TOO_LARGE_RADIUS "1e20"
#else
#define OVERFLOWING "1e999"
#define TOO_LARGE_RADIUS "1e200"
#endif

/* sRGB-decoded scene colours (reference values from the IEC 61966-2-1 formula). */
#define LIN_05 0.21404114048223255  /* decode(0.5) */
#define LIN_025 0.05087608817155679 /* decode(0.25) */
#define LIN_02 0.033104766570885055 /* decode(0.2) */
#define LIN_002 0.0015479876160990713 /* decode(0.02): the linear segment, 0.02 / 12.92 */

/* ---- NFF entities ---------------------------------------------------------------- */

static void test_view(void)
{
	EXPECT_OK("v\nfrom 1 2 -10\nat 0.5 0 0\nup 0 1 0.25\nangle 37.5\nhither 0.01\n"
		  "resolution 640 480\n");
	CHECK_VEC(sc.camera.from, 1, 2, -10);
	CHECK_VEC(sc.camera.at, 0.5, 0, 0);
	/* up is kept as given: the camera orthonormalises it, not the parser. */
	CHECK_VEC(sc.camera.up, 0, 1, 0.25);
	CHECK_REAL(sc.camera.angle, 37.5, EPS);
	CHECK_REAL(sc.camera.hither, 0.01, EPS);
	CHECK_INT(sc.camera.width, 640);
	CHECK_INT(sc.camera.height, 480);
	/* Defaults of everything the view does not set. */
	CHECK_VEC(sc.background, 0, 0, 0);
	CHECK_VEC(sc.ambient, 0, 0, 0);
	CHECK_INT(sc.depth, RT_DEFAULT_DEPTH);
	CHECK_REAL(sc.cutoff, 1.0 / 256, EPS);
	CHECK(sc.file != NULL && strcmp(sc.file, FILE_NAME) == 0);
}

static void test_background(void)
{
	EXPECT_OK(VIEW "b 1 1 1\n");
	CHECK_VEC(sc.background, 1, 1, 1);
	EXPECT_OK(VIEW "b 0.5 0.25 0\n");
	CHECK_VEC(sc.background, LIN_05, LIN_025, 0);
	/* SPD writes `b` before `v`. */
	EXPECT_OK("b 0.5 0.5 0.5\n" VIEW);
	CHECK_VEC(sc.background, LIN_05, LIN_05, LIN_05);
	CHECK_REAL(sc.background.x, 0.214, 1e-4);
	/* The linear segment of the curve. */
	EXPECT_OK(VIEW "b 0.02 0 1\n");
	CHECK_VEC(sc.background, LIN_002, 0, 1);
}

static void test_lights(void)
{
	/* Without a colour each of N lights gets 1/sqrt(N). */
	EXPECT_OK(VIEW "l 1 2 3\nl -4 5 -6\n");
	CHECK_INT(sc.light_count, 2);
	CHECK_VEC(sc.lights[0].position, 1, 2, 3);
	CHECK_VEC(sc.lights[1].position, -4, 5, -6);
	CHECK_VEC(sc.lights[0].color, 0.7071067811865475, 0.7071067811865475, 0.7071067811865475);
	CHECK_VEC(sc.lights[1].color, 0.7071067811865475, 0.7071067811865475, 0.7071067811865475);

	EXPECT_OK(VIEW "l 0 10 0\n");
	CHECK_INT(sc.light_count, 1);
	CHECK_VEC(sc.lights[0].color, 1, 1, 1);

	/* A colour on the same line is kept as a linear intensity (not sRGB-decoded); N still
	 * counts every light. */
	EXPECT_OK(VIEW "l 1 2 3 0.5 0.25 2\nl 0 0 0\nl 9 9 9 # white-ish\n");
	CHECK_INT(sc.light_count, 3);
	CHECK_VEC(sc.lights[0].position, 1, 2, 3);
	CHECK_VEC(sc.lights[0].color, 0.5, 0.25, 2);
	CHECK_VEC(sc.lights[1].color, 0.5773502691896258, 0.5773502691896258, 0.5773502691896258);
	CHECK_VEC(sc.lights[2].position, 9, 9, 9);
	CHECK_VEC(sc.lights[2].color, 0.5773502691896258, 0.5773502691896258, 0.5773502691896258);

	/* Followed directly by another entity on the same line. */
	EXPECT_OK(VIEW "l 1 1 1 s 0 0 0 1\n");
	CHECK_INT(sc.light_count, 1);
	CHECK_INT(sc.object_count, 1);
	CHECK_VEC(sc.lights[0].color, 1, 1, 1);

	/* Last thing in the file, with no newline. */
	EXPECT_OK(VIEW "l 1 1 1");
	CHECK_INT(sc.light_count, 1);
	CHECK_VEC(sc.lights[0].color, 1, 1, 1);

	/* A colour must be on the light's line: numbers on the next line are not one. */
	EXPECT_ERROR(VIEW "l 1 2 3\n0.5 0.5 0.5\n", 9, "unknown command '0.5'");
	/* The end of the file is reported on its last line. */
	EXPECT_ERROR(VIEW "l 1 2 3 1 1\n", 8,
		     "unexpected end of file (expected a number (light colour))");
}

static void test_materials(void)
{
	EXPECT_OK(VIEW "f 0.5 1 0 0.7 0.3 45.28 0 0\ns 0 0 0 1\n");
	CHECK_INT(sc.material_count, 1);
	CHECK_VEC(sc.materials[0].color, LIN_05, 1, 0);
	CHECK_REAL(sc.materials[0].kd, 0.7, EPS);
	CHECK_REAL(sc.materials[0].ks, 0.3, EPS);
	CHECK_REAL(sc.materials[0].shine, 45.28, TOL3(1e-4, 1e-12, 0.5 * LSB)); /* read once */
	CHECK_REAL(sc.materials[0].kt, 0, 0);
	/* An opaque material's ior means nothing and is stored as 1. */
	CHECK_REAL(sc.materials[0].ior, 1, 0);
	check_vec(sc.materials[0].absorb, 0, 0, 0, 0, __LINE__);
	CHECK_INT(sc.objects[0].material, 0);

	EXPECT_OK(VIEW "f 0.25 0.25 0.25 0 0 0 0.9 1.5\ns 0 0 0 1\n");
	CHECK_VEC(sc.materials[0].color, LIN_025, LIN_025, LIN_025);
	CHECK_REAL(sc.materials[0].kt, 0.9, EPS);
	CHECK_REAL(sc.materials[0].ior, 1.5, EPS);

	/* Identical `f` lines share one material; opaque ior 0 and 1 are identical too. */
	EXPECT_OK(VIEW "f 1 0 0 1 0 0 0 0\ns 0 0 0 1\nf 1 0 0 1 0 0 0 1\ns 0 0 3 1\n"
		       "f 0 1 0 1 0 0 0 1\ns 0 0 6 1\nf 1 0 0 1 0 0 0 1\ns 0 0 9 1\n");
	CHECK_INT(sc.material_count, 2);
	CHECK_INT(sc.object_count, 4);
	CHECK_INT(sc.objects[0].material, 0);
	CHECK_INT(sc.objects[1].material, 0);
	CHECK_INT(sc.objects[2].material, 1);
	CHECK_INT(sc.objects[3].material, 0);

	/* Before any `f`: white, fully diffuse. */
	EXPECT_OK(VIEW "s 0 0 0 1\n");
	CHECK_INT(sc.material_count, 1);
	CHECK_VEC(sc.materials[0].color, 1, 1, 1);
	CHECK_REAL(sc.materials[0].kd, 1, 0);
	CHECK_REAL(sc.materials[0].ks, 0, 0);
	CHECK_REAL(sc.materials[0].kt, 0, 0);

	/* A transmitting material needs an index of refraction. */
	EXPECT_ERROR(VIEW "f 1 1 1 0 0 0 0.5 0\n", 8,
		     "material: T > 0 needs an index of refraction > 0, got 0");
	EXPECT_ERROR(VIEW "f 1 1 1 -0.5 0 0 0 1\n", 8, "material Kd must not be negative, got -0.5");
	/* Each value is named at its own token, whatever line the rest is on. */
	EXPECT_ERROR(VIEW "f 1 -0.5 1\n1 0 0 0 1\n", 8,
		     "material colour must not be negative, got -0.5");
	EXPECT_ERROR(VIEW "f 1 1 1\n1 0 0 -1 1\n", 9, "material T must not be negative, got -1");
	EXPECT_ERROR(VIEW "f 1 1 1 1 0 0 0\ns 0 0 0 1\n", 9,
		     "expected a number (material index of refraction), got 's'");
}

static void test_sphere(void)
{
	EXPECT_OK(VIEW "s 1 -2 3.5 0.5\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].kind, SHAPE_SPHERE);
	CHECK_INT(sc.objects[0].line, 8);
	CHECK_VEC(sc.objects[0].u.sphere.center, 1, -2, 3.5);
	CHECK_REAL(sc.objects[0].u.sphere.radius, 0.5, 0);
	CHECK_REAL2(sc.objects[0].u.sphere.radius2, 0.25, 0);
	/* A closed solid is seen from both sides, and not only from inside. */
	CHECK_INT(sc.objects[0].flags, OBJ_TWO_SIDED);

	/* NFF: a negative radius is valid and shows only the inside. */
	EXPECT_OK(VIEW "s 0 0 0 -2\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_REAL(sc.objects[0].u.sphere.radius, 2, 0);
	CHECK_REAL2(sc.objects[0].u.sphere.radius2, 4, 0);
	CHECK_INT(sc.objects[0].flags, OBJ_TWO_SIDED | OBJ_INSIDE_ONLY);

	/* Radius 0 cannot be seen: a warning, and the object is skipped. */
	CHECK_INT(PARSE(VIEW "s 0 0 0 0\ns 0 0 5 1\n"), 1);
	CHECK_STR(messages, "rt: " FILE_NAME ":8: warning: sphere with radius 0; skipped\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_VEC(sc.objects[0].u.sphere.center, 0, 0, 5);
	CHECK_INT(sc.objects[0].line, 9);
	EXPECT_WARNING(VIEW "s 0 0 0 -0\n", 8, "sphere with radius 0; skipped");
	CHECK_INT(sc.object_count, 0);
}

static void test_polygon(void)
{
	int i;
	/* Counter-clockwise seen from +z: the normal is +z; the plane is z = 2. */
	EXPECT_OK(VIEW "p 3\n0 0 2\n1 0 2\n0 1 2\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].kind, SHAPE_POLYGON);
	CHECK_INT(sc.objects[0].line, 8);
	/* Opaque polygons are one-sided. */
	CHECK_INT(sc.objects[0].flags, 0);
	CHECK_VEC(dir_to_vec(sc.objects[0].u.polygon.normal), 0, 0, 1);
	CHECK_REAL(sc.objects[0].u.polygon.offset, 2, EPS);
	CHECK_INT(sc.objects[0].u.polygon.first, 0);
	CHECK_INT(sc.objects[0].u.polygon.count, 3);
	CHECK_INT(sc.objects[0].u.polygon.axis, 2);
	CHECK_INT(sc.vertex_count, 3);
	CHECK_VEC(sc.vertices[1], 1, 0, 2);

	/* A second polygon's vertices follow the first's; its normal follows its winding (-x
	 * here). A transmitting polygon is two-sided. */
	EXPECT_OK(VIEW "p 3\n0 0 0\n1 0 0\n0 1 0\nf 1 1 1 0 0 0 0.5 1.5\n"
		       "p 4\n3 0 0\n3 0 1\n3 1 1\n3 1 0\n");
	CHECK_INT(sc.object_count, 2);
	CHECK_INT(sc.objects[1].u.polygon.first, 3);
	CHECK_INT(sc.objects[1].u.polygon.count, 4);
	CHECK_VEC(dir_to_vec(sc.objects[1].u.polygon.normal), -1, 0, 0);
	CHECK_REAL(sc.objects[1].u.polygon.offset, -3, EPS);
	CHECK_INT(sc.objects[1].u.polygon.axis, 0);
	CHECK_INT(sc.objects[1].flags, OBJ_TWO_SIDED);
	CHECK_INT(sc.objects[1].line, 13);
	CHECK_INT(sc.vertex_count, 7);
	CHECK_VEC(sc.vertices[6], 3, 1, 0);

	/* Clockwise seen from +z: the normal is -z. */
	EXPECT_OK(VIEW "p 3\n0 0 -1\n0 1 -1\n1 0 -1\n");
	CHECK_VEC(dir_to_vec(sc.objects[0].u.polygon.normal), 0, 0, -1);
	CHECK_REAL(sc.objects[0].u.polygon.offset, 1, EPS);

	/* Concave (a notched square, the reflex corner at (2, 1)): kept whole, in order. */
	EXPECT_OK(VIEW "p 5\n0 0 0\n4 0 0\n4 4 0\n2 1 0\n0 4 0\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].u.polygon.count, 5);
	CHECK_VEC(dir_to_vec(sc.objects[0].u.polygon.normal), 0, 0, 1);
	CHECK_REAL(sc.objects[0].u.polygon.offset, 0, EPS);
	for (i = 0; i < 5; i++) {
		static const double xy[5][2] = {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
		CHECK_VEC(sc.vertices[i], xy[i][0], xy[i][1], 0);
	}

	/* Zero area: a warning, skipped, and its vertices are not kept. */
	CHECK_INT(PARSE(VIEW "p 3\n0 0 0\n1 1 1\n2 2 2\np 3\n0 0 0\n0 1 0\n0 0 1\n"), 1);
	CHECK_STR(messages, "rt: " FILE_NAME ":8: warning: polygon with zero area; skipped\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].u.polygon.first, 0);
	CHECK_INT(sc.vertex_count, 3);
	CHECK_VEC(dir_to_vec(sc.objects[0].u.polygon.normal), 1, 0, 0);
	EXPECT_WARNING(VIEW "p 4\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n", 8, "polygon with zero area");
	CHECK_INT(sc.object_count, 0);
	/* A symmetric bow-tie: its signed areas cancel, but the even-odd rule fills both
	 * lobes. It is kept, in the plane of its first corner (z = 0, normal +z there). */
	EXPECT_OK(VIEW "p 4\n-1 -1 0\n1 1 0\n1 -1 0\n-1 1 0\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_VEC(dir_to_vec(sc.objects[0].u.polygon.normal), 0, 0, -1);
	CHECK_REAL(sc.objects[0].u.polygon.offset, 0, EPS);
}

static void test_patch(void)
{
	/* Vertex normals are normalised; a zero one falls back to the face normal. */
	EXPECT_OK(VIEW "pp 3\n0 0 0 0 0 2\n1 0 0 0 0 0\n0 1 0 1 0 1\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].kind, SHAPE_PATCH);
	CHECK_INT(sc.objects[0].flags, OBJ_TWO_SIDED);
	CHECK_VEC(dir_to_vec(sc.objects[0].u.polygon.normal), 0, 0, 1);
	CHECK_INT(sc.objects[0].u.polygon.count, 3);
	CHECK_VEC(sc.vertices[2], 0, 1, 0);
	CHECK_VEC(dir_to_vec(sc.normals[0]), 0, 0, 1);
	CHECK_VEC(dir_to_vec(sc.normals[1]), 0, 0, 1);
	CHECK_VEC(dir_to_vec(sc.normals[2]), 0.7071067811865475, 0, 0.7071067811865475);
	EXPECT_WARNING(VIEW "pp 3\n0 0 0 0 0 1\n0 0 0 0 0 1\n0 0 0 0 0 1\n", 8,
		       "patch with zero area; skipped");
	EXPECT_ERROR(VIEW "pp 3\n0 0 0 0 0 1\n1 0 0\n", 10,
		     "unexpected end of file (expected a number (patch vertex normal))");
}

static void test_cone(void)
{
	EXPECT_OK(VIEW "c 0 0 0 2 0 0 4 1\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].kind, SHAPE_CONE);
	CHECK_INT(sc.objects[0].flags, OBJ_TWO_SIDED);
	CHECK_VEC(sc.objects[0].u.cone.base, 0, 0, 0);
	CHECK_VEC(dir_to_vec(sc.objects[0].u.cone.axis), 0, 0, 1);
	CHECK_REAL(sc.objects[0].u.cone.length, 4, EPS);
	CHECK_REAL(sc.objects[0].u.cone.base_radius, 2, 0);
	CHECK_REAL(sc.objects[0].u.cone.apex_radius, 1, 0);
	CHECK_REAL(sc.objects[0].u.cone.slope, -0.25, EPS);

	/* A cylinder: equal radii, zero slope. */
	EXPECT_OK(VIEW "c 1 1 1 0.5 1 3 1 0.5\n");
	CHECK_VEC(dir_to_vec(sc.objects[0].u.cone.axis), 0, 1, 0);
	CHECK_REAL(sc.objects[0].u.cone.length, 2, EPS);
	CHECK_REAL(sc.objects[0].u.cone.slope, 0, 0);

	/* Both radii negative: inside only. */
	EXPECT_OK(VIEW "c 0 0 0 -1 0 0 1 -0.5\n");
	CHECK_INT(sc.objects[0].flags, OBJ_TWO_SIDED | OBJ_INSIDE_ONLY);
	CHECK_REAL(sc.objects[0].u.cone.base_radius, 1, 0);
	CHECK_REAL(sc.objects[0].u.cone.apex_radius, 0.5, 0);

	EXPECT_ERROR(VIEW "c 0 0 0 -1 0 0 1 1\n", 8,
		     "cone: both radii must have the same sign, got base radius < 0 and apex "
		     "radius 1");
	EXPECT_ERROR(VIEW "c 0 0 0 0 0 0 1 -1\n", 8,
		     "cone: both radii must have the same sign, got base radius >= 0 and apex "
		     "radius -1");
	EXPECT_WARNING(VIEW "c 1 2 3 1 1 2 3 1\n", 8, "cone with zero length; skipped");
	EXPECT_WARNING(VIEW "c 0 0 0 0 0 0 1 0\n", 8, "cone with both radii 0; skipped");
}

/* ---- extensions ---------------------------------------------------------------------- */

static void test_settings(void)
{
	/* ambient is a linear intensity like a light's colour. */
	EXPECT_OK(VIEW "ambient 0.1 0.2 0.5\n");
	CHECK_VEC(sc.ambient, 0.1, 0.2, 0.5);

	EXPECT_OK(VIEW "depth 3\n");
	CHECK_INT(sc.depth, 3);
	EXPECT_OK(VIEW "depth 1\n");
	CHECK_INT(sc.depth, 1);
	EXPECT_OK(VIEW "depth " STR(RT_MAX_DEPTH) "\n");
	CHECK_INT(sc.depth, RT_MAX_DEPTH);
	EXPECT_ERROR(VIEW "depth 0\n", 8, "depth must be 1 to " STR(RT_MAX_DEPTH) ", got 0");
	EXPECT_ERROR(VIEW "depth 99\n", 8,
		     "depth 99 is over the limit RT_MAX_DEPTH = " STR(RT_MAX_DEPTH));
	EXPECT_ERROR(VIEW "depth 2.5\n", 8, "expected depth (a whole number), got '2.5'");

	EXPECT_OK(VIEW "cutoff 0.125\n");
	CHECK_REAL(sc.cutoff, 0.125, 0);
	EXPECT_OK(VIEW "cutoff 0\n");
	CHECK_REAL(sc.cutoff, 0, 0);
	EXPECT_ERROR(VIEW "cutoff 1\n", 8, "cutoff weight must be in [0, 1), got 1");
	EXPECT_ERROR(VIEW "cutoff -0.5\n", 8, "cutoff weight must be in [0, 1), got -0.5");
}

static void test_absorb(void)
{
	/* absorb applies to the next `f` only; it also keeps that material apart. One
	 * number absorbs all three channels alike. */
	EXPECT_OK(VIEW "absorb 0.5\nf 1 1 1 0 0 0 0.9 1.5\ns 0 0 0 1\n"
		       "f 1 1 1 0 0 0 0.9 1.5\ns 0 0 3 1\n");
	CHECK_INT(sc.material_count, 2);
	check_vec(sc.materials[0].absorb, 0.5, 0.5, 0.5, 0, __LINE__);
	check_vec(sc.materials[1].absorb, 0, 0, 0, 0, __LINE__);
	CHECK_INT(sc.objects[0].material, 0);
	CHECK_INT(sc.objects[1].material, 1);

	/* Three numbers on the line: per channel. The next line's numbers are not part of it. */
	EXPECT_OK(VIEW "absorb 1.8 0.7 0.25\nf 1 1 1 0 0 0 0.9 1.5\ns 0 0 0 1\n");
	check_vec(sc.materials[0].absorb, 1.8, 0.7, 0.25, EPS, __LINE__);
	EXPECT_OK(VIEW "absorb 2 # grey\nf 1 1 1 0 0 0 0.9 1.5\ns 0 0 0 1\n");
	check_vec(sc.materials[0].absorb, 2, 2, 2, 0, __LINE__);
	EXPECT_ERROR(VIEW "absorb 2\n0.5 0.5\n", 9, "unknown command '0.5'");

	/* Without a following `f` it sets nothing. */
	EXPECT_OK(VIEW "f 1 1 1 0 0 0 0.9 1.5\nabsorb 3\ns 0 0 0 1\n");
	check_vec(sc.materials[0].absorb, 0, 0, 0, 0, __LINE__);

	/* Reported at the bad number, not at whatever the look-ahead found after it. */
	EXPECT_ERROR(VIEW "absorb -1\n", 8, "absorption coefficient must not be negative, got -1");
	EXPECT_ERROR(VIEW "absorb -1\ns 0 0 0 1\n", 8,
		     "absorption coefficient must not be negative, got -1");
	EXPECT_ERROR(VIEW "absorb 1 -2 1\n", 8,
		     "absorption coefficient must not be negative, got -2");
	EXPECT_ERROR(VIEW "absorb 1 1 -2\n", 8,
		     "absorption coefficient must not be negative, got -2");
	EXPECT_ERROR(VIEW "absorb 1 1\n", 8,
		     "unexpected end of file (expected a number (absorption coefficient))");
}

static void test_plane(void)
{
	EXPECT_OK(VIEW "plane 0 -1 0 0 2 0\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].kind, SHAPE_PLANE);
	CHECK_INT(sc.objects[0].flags, OBJ_TWO_SIDED);
	CHECK_VEC(dir_to_vec(sc.objects[0].u.plane.normal), 0, 1, 0);
	CHECK_REAL(sc.objects[0].u.plane.offset, -1, EPS);
	EXPECT_OK(VIEW "plane 1 1 1 3 0 4\n");
	CHECK_VEC(dir_to_vec(sc.objects[0].u.plane.normal), 0.6, 0, 0.8);
	CHECK_REAL(sc.objects[0].u.plane.offset, 1.4, EPS);
	EXPECT_ERROR(VIEW "plane 0 0 0 0 0 0\n", 8, "plane: the normal is zero");
}

static void test_box(void)
{
	/* Corners in any order: six half-spaces n.x <= d with unit normals. */
	static const double expect[6][4] = {{1, 0, 0, 1},  {-1, 0, 0, 1}, {0, 1, 0, 2},
					     {0, -1, 0, 2}, {0, 0, 1, 3},  {0, 0, -1, 3}};
	int i;
	EXPECT_OK(VIEW "box 1 2 3 -1 -2 -3\n");
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].kind, SHAPE_HEDRON);
	CHECK_INT(sc.objects[0].flags, OBJ_TWO_SIDED);
	CHECK_INT(sc.objects[0].u.hedron.first, 0);
	CHECK_INT(sc.objects[0].u.hedron.count, 6);
	CHECK_INT(sc.plane_count, 6);
	for (i = 0; i < 6; i++) {
		/* Exact: unit axes and whole offsets survive normalisation unrounded. */
		check_vec(dir_to_vec(sc.planes[i].normal), expect[i][0], expect[i][1], expect[i][2], 0,
			  __LINE__);
		CHECK_REAL(sc.planes[i].offset, expect[i][3], 0);
	}
	EXPECT_WARNING(VIEW "box 0 0 0 1 1 0\n", 8, "box with zero thickness; skipped");
	CHECK_INT(sc.plane_count, 0);
}

static void test_polyhedron(void)
{
	EXPECT_OK(VIEW "box 0 0 0 1 1 1\npolyhedron 3\n0 0 2 4\n-1 0 0 1\n0 3 4 10\n");
	CHECK_INT(sc.object_count, 2);
	CHECK_INT(sc.objects[1].kind, SHAPE_HEDRON);
	CHECK_INT(sc.objects[1].line, 9);
	CHECK_INT(sc.objects[1].u.hedron.first, 6);
	CHECK_INT(sc.objects[1].u.hedron.count, 3);
	CHECK_INT(sc.plane_count, 9);
	/* Normalised, with the offset divided by the same length. */
	CHECK_VEC(dir_to_vec(sc.planes[6].normal), 0, 0, 1);
	CHECK_REAL(sc.planes[6].offset, 2, EPS);
	CHECK_VEC(dir_to_vec(sc.planes[7].normal), -1, 0, 0);
	CHECK_REAL(sc.planes[7].offset, 1, EPS);
	CHECK_VEC(dir_to_vec(sc.planes[8].normal), 0, 0.6, 0.8);
	CHECK_REAL(sc.planes[8].offset, 2, EPS);
	EXPECT_ERROR(VIEW "polyhedron 2\n1 0 0 1\n0 0 0 1\n", 10,
		     "polyhedron: a plane normal is zero");
	EXPECT_ERROR(VIEW "polyhedron 0\n", 8,
		     "polyhedron plane count must be 1 to " STR(RT_MAX_HEDRON_PLANES) ", got 0");
	EXPECT_ERROR(VIEW "polyhedron 2\n1 0 0 1\n", 9,
		     "unexpected end of file (expected a number (polyhedron plane normal))");
}

/* ---- unusual but valid input ------------------------------------------------------- */

static void test_unusual_valid(void)
{
	/* CRLF line ends: same values, same line numbers. */
	EXPECT_OK("v\r\nfrom 0 0 -10\r\nat 0 0 0\r\nup 0 1 0\r\nangle 45\r\nhither 1\r\n"
		  "resolution 32 24\r\ns 0 0 0 1\r\nl 1 2 3\r\n");
	CHECK_INT(sc.camera.height, 24);
	CHECK_INT(sc.object_count, 1);
	CHECK_INT(sc.objects[0].line, 8);
	CHECK_REAL(sc.objects[0].u.sphere.radius, 1, 0);
	CHECK_VEC(sc.lights[0].color, 1, 1, 1);
	EXPECT_WARNING("v\r\nfrom 0 0 -10\r\nat 0 0 0\r\nup 0 1 0\r\nangle 45\r\nhither 1\r\n"
		       "resolution 32 24\r\n\r\ns 0 0 0 0\r\n",
		       9, "sphere with radius 0");

	/* Tabs, and the whole view on one line (NFF is a token stream). */
	EXPECT_OK("v\tfrom\t0 0 -10\tat 0 0 0 up\t0 1 0 angle 45 hither 1 resolution\t8 6\n"
		  "s\t1\t2\t3\t4\n");
	CHECK_INT(sc.camera.width, 8);
	CHECK_VEC(sc.objects[0].u.sphere.center, 1, 2, 3);
	CHECK_INT(sc.objects[0].line, 2);

	/* Comments anywhere: before everything, after numbers (with and without a space),
	 * between vertices, and at the very end without a newline. */
	EXPECT_OK("# a scene\n" VIEW "s 0 0 0 1# radius\np 3 # triangle\n0 0 0 # first\n"
		  "# between vertices\n1 0 0\n  # indented\n0 1 0\nl 1 1 1 # a light\n# end");
	CHECK_INT(sc.object_count, 2);
	CHECK_REAL(sc.objects[0].u.sphere.radius, 1, 0);
	CHECK_INT(sc.objects[0].line, 9);
	CHECK_INT(sc.objects[1].line, 10);
	CHECK_VEC(sc.vertices[1], 1, 0, 0);
	CHECK_VEC(sc.vertices[2], 0, 1, 0);
	CHECK_INT(sc.light_count, 1);
	CHECK_VEC(sc.lights[0].color, 1, 1, 1);
	/* A comment holds any bytes. */
	EXPECT_OK(VIEW "# caf\xC3\xA9 \x01\x7F\n");

	/* No final newline. */
	EXPECT_OK(VIEW "s 0 0 0 2");
	CHECK_REAL(sc.objects[0].u.sphere.radius, 2, 0);

	/* Exponents as %g writes them. */
	EXPECT_OK(VIEW "s 1e-3 1.11022e-16 -2.55836e-17 2.5E+1\n");
	/* Q16.16: read to the nearest LSB (1e-3 is 66), and the others are below it: 0. */
	CHECK_REAL(sc.objects[0].u.sphere.center.x, 1e-3, TOL3(1e-10, 1e-15, 0.5 * LSB));
	CHECK_REAL(sc.objects[0].u.sphere.center.y, 1.11022e-16, TOL3(1e-22, 1e-22, 0.5 * LSB));
	CHECK_REAL(sc.objects[0].u.sphere.center.z, -2.55836e-17, TOL3(1e-23, 1e-23, 0.5 * LSB));
	CHECK_REAL(sc.objects[0].u.sphere.radius, 25, 0);

	/* `b` after `v`, `l` between objects. */
	EXPECT_OK(VIEW "s 0 0 0 1\nb 0.2 0.2 0.2\nl 0 5 0\n");
	CHECK_VEC(sc.background, LIN_02, LIN_02, LIN_02);
	CHECK_INT(sc.light_count, 1);

	/* Nothing but a view: no objects and no lights is a valid (empty) scene. */
	EXPECT_OK(VIEW);
	CHECK_INT(sc.object_count, 0);
	CHECK_INT(sc.light_count, 0);
	CHECK_INT(sc.material_count, 0);

	/* A UTF-8 byte-order mark is skipped and does not shift line numbers. */
	EXPECT_WARNING("\xEF\xBB\xBF" VIEW "s 0 0 0 0\n", 8, "sphere with radius 0");
	EXPECT_OK("\xEF\xBB\xBF" VIEW);
	CHECK_INT(sc.camera.width, 32);

	/* Blank lines before the first token count once each. */
	EXPECT_WARNING("\n\n" VIEW "s 0 0 0 0\n", 10, "sphere with radius 0");
	EXPECT_WARNING("\n" VIEW "s 0 0 0 0\n", 9, "sphere with radius 0");
	EXPECT_WARNING("\r\n" VIEW "s 0 0 0 0\n", 9, "sphere with radius 0");
	EXPECT_WARNING(" \n" VIEW "s 0 0 0 0\n", 9, "sphere with radius 0");

	/* Every whitespace byte separates tokens. */
	EXPECT_OK(VIEW "s\f1\v2 3\r4\n");
	CHECK_REAL(sc.objects[0].u.sphere.radius, 4, 0);
}

/* ---- malformed input ---------------------------------------------------------------- */

static void test_numbers(void)
{
	EXPECT_ERROR(VIEW "s 1 2 3\n", 8,
		     "unexpected end of file (expected a number (sphere radius))");
	EXPECT_ERROR(VIEW "s 1 2 3\ns 0 0 0 1\n", 9, "expected a number (sphere radius), got 's'");
	EXPECT_ERROR(VIEW "s 0 0 zero 1\n", 8, "expected a number (sphere centre), got 'zero'");
	EXPECT_ERROR(VIEW "s 0 0 0 1.0x\n", 8, "expected a number (sphere radius), got '1.0x'");
	EXPECT_ERROR(VIEW "s 0 0 0 1,5\n", 8, "got '1,5'");
	EXPECT_ERROR(VIEW "s nan 0 0 1\n", 8,
		     "expected a number (sphere centre), got 'nan' (not a finite number)");
	EXPECT_ERROR(VIEW "s 0 0 0 inf\n", 8, "got 'inf' (not a finite number)");
	EXPECT_ERROR(VIEW "s 0 0 0 -infinity\n", 8, "got '-infinity' (not a finite number)");
#if !REAL_FIXED
	EXPECT_ERROR(VIEW "s 0 0 " OVERFLOWING " 1\n", 8,
		     "got '" OVERFLOWING "' (not a finite number)");
	EXPECT_ERROR(VIEW "s 0 0 -1e99999 1\n", 8, "got '-1e99999' (not a finite number)");
	EXPECT_ERROR(VIEW "s 0 0 0 " TOO_LARGE_RADIUS "\n", 8,
		     "expected a number (sphere radius) within +-1e12, got '" TOO_LARGE_RADIUS
		     "' (out of range)");
	EXPECT_OK(VIEW "s 1e12 0 0 1\n");
	EXPECT_ERROR(VIEW "s -1.0000001e12 0 0 1\n", 8, "within +-1e12");
#else
	/* Q16.16 has no infinity: a number past its range is out of range, not infinite.
	 * parse_scene reads at scale 1, where the range ends at 32768 (scene files are
	 * scaled to fit first: test_range_refusals). */
	EXPECT_ERROR(VIEW "s 0 0 1e999 1\n", 8,
		     "expected a number (sphere centre) within " REAL_RANGE_TEXT
		     ", got '1e999' (out of range)");
	EXPECT_ERROR(VIEW "s 0 0 -1e99999 1\n", 8, "got '-1e99999' (out of range)");
	EXPECT_OK(VIEW "s 32767 0 0 1\n");
	EXPECT_ERROR(VIEW "s -32768 0 0 1\n", 8, "within " REAL_RANGE_TEXT);
#endif
	EXPECT_ERROR(VIEW "l 1 2\n", 8,
		     "unexpected end of file (expected a number (light position))");
	EXPECT_ERROR(VIEW "b 1 1\n", 8, "expected a number (background colour)");
	EXPECT_ERROR(VIEW "ambient 0.1 x 0.1\n", 8, "expected a number (ambient colour), got 'x'");
	EXPECT_ERROR(VIEW "f 1 1 1 1 0 0 0 nan\n", 8, "not a finite number");
	EXPECT_ERROR(VIEW "c 0 0 0 1 0 0\n", 8, "expected a number (cone apex centre)");
	EXPECT_ERROR(VIEW "plane 0 0 0 0 1\n", 8, "expected a number (plane normal)");
	EXPECT_ERROR(VIEW "box 0 0 0 1 1 one\n", 8, "expected a number (box corner), got 'one'");

	/* The end of the file is its last line, even after blank lines and comments. */
	EXPECT_ERROR(VIEW "s 1 2 3\n\n# end\n", 10, "unexpected end of file");
	EXPECT_ERROR(VIEW "s 1 2 3 # no newline", 8, "unexpected end of file");

	/* An extra number is read as a command: the message says what it probably is. */
	EXPECT_ERROR(VIEW "s 0 0 0 1 2\n", 8,
		     "unknown command '2' (a number: one too many before it?)");
	EXPECT_ERROR(VIEW "s 0 0 0 1 nan\n", 8, "unknown command 'nan' (a number: one too many");

	/* Only the first error is reported; later ones would be its consequences. */
	EXPECT_ERROR(VIEW "s 0 0 x 1\nfoo\nbar 1\n", 8, "got 'x'");
}

static void test_polygon_counts(void)
{
	char text[256];
	EXPECT_ERROR(VIEW "p 2\n0 0 0\n1 0 0\n", 8,
		     "polygon vertex count must be 3 to " STR(RT_MAX_POLY_VERTS) ", got 2");
	EXPECT_ERROR(VIEW "p -3\n", 8, "polygon vertex count must be 3 to");
	EXPECT_ERROR(VIEW "p 1000000000\n", 8,
		     "polygon vertex count 1000000000 is over the limit RT_MAX_POLY_VERTS = " STR(
			     RT_MAX_POLY_VERTS) " (raise it in src/config.h)");
	/* Beyond long: still the limit message. */
	EXPECT_ERROR(VIEW "p 99999999999999999999999\n", 8, "is over the limit RT_MAX_POLY_VERTS");
	EXPECT_ERROR(VIEW "p three\n", 8,
		     "expected polygon vertex count (a whole number), got 'three'");
	EXPECT_ERROR(VIEW "pp 2\n", 8, "patch vertex count must be 3 to");
	EXPECT_ERROR(VIEW "p 3\n0 0 0\n1 0 0\n", 10,
		     "unexpected end of file (expected a number (polygon vertex))");
	/* One past the capacity, whatever the build set it to. */
	snprintf(text, sizeof text, "%sp %d\n", VIEW, RT_MAX_POLY_VERTS + 1);
	expect_message(text, strlen(text), 0, 8, "is over the limit RT_MAX_POLY_VERTS", __LINE__);
}

static void test_view_errors(void)
{
	EXPECT_ERROR("v\nfrom 0 0 -10\nup 0 1 0\nat 0 0 0\n", 3, "view: expected 'at', got 'up'");
	EXPECT_ERROR("v\nat 0 0 0\n", 2, "view: expected 'from', got 'at'");
	EXPECT_ERROR("v\nfrom 0 0 -10\nat 0 0 0\nup 0 1 0\nangle 45\nresolution 4 4\n", 6,
		     "view: expected 'hither', got 'resolution'");
	EXPECT_ERROR("v\nfrom 0 0 -10\n", 2, "unexpected end of file (expected view at)");
	EXPECT_ERROR("v\nfrom 0 0\nat 0 0 0\n", 3, "expected a number (view from), got 'at'");

	/* No view at all: reported at the end of the file, its last line. */
	EXPECT_ERROR("s 0 0 0 1\nl 1 1 1\n", 2, "no view: a scene needs a 'v' entity");
	EXPECT_ERROR("", 1, "no view");
	EXPECT_ERROR("# only a comment", 1, "no view");

	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "0", "32 24"), 5,
		     "view angle must be between 0 and 180 degrees, got 0");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "180", "32 24"), 5,
		     "view angle must be between 0 and 180 degrees, got 180");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "-30", "32 24"), 5,
		     "view angle must be between 0 and 180 degrees, got -30");
	EXPECT_OK(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "179.9", "32 24"));
	/* An angle the type rounds to 180 is refused with what it became, not as if the
	 * text were out of range (float and Q16.16 hold 179.99999999 as 180). */
#if defined(RT_REAL_FLOAT) || REAL_FIXED
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "179.99999999", "32 24"), 5,
		     "got 179.99999999 (180");
#else
	EXPECT_OK(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "179.99999999", "32 24"));
#endif
	/* Numbers are decimal in every build: no hexadecimal floats. */
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "0x28", "32 24"), 5,
		     "expected a number (view angle), got '0x28'");
	EXPECT_OK(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "0.01", "32 24"));

	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "45", "0 24"), 7,
		     "resolution width must be 1 to " STR(RT_MAX_SCENE_WIDTH) ", got 0");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "45", "32 0"), 7,
		     "resolution height must be 1 to " STR(RT_MAX_SCENE_HEIGHT) ", got 0");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "45", "32.5 24"), 7,
		     "expected resolution width (a whole number), got '32.5'");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "45", "100000 24"), 7,
		     "resolution width 100000 is over the limit RT_MAX_SCENE_WIDTH");
	EXPECT_OK(VIEW_WITH("0 0 -10", "0 0 0", "0 1 0", "45", "1 1"));

	/* Degenerate cameras are reported at the `v` line. */
	EXPECT_ERROR(VIEW_WITH("1 2 3", "1 2 3", "0 1 0", "45", "32 24"), 1,
		     "view: the distance from 'from' to 'at' is zero");
	/* Numbers too small for the type are named so, in every type: 1e-3000 is a long
	 * double, whose square is not; it is no double, no float and no Q16.16. */
	EXPECT_ERROR(VIEW_WITH("0 0 1e-3000", "0 0 0", "0 1 0", "45", "32 24"), 1,
		     "view: the distance from 'from' to 'at' is too small to represent in ");
	EXPECT_ERROR(VIEW "plane 0 0 0 0 1e-3000 0\n", 8,
		     "plane: the normal is too small to represent in ");
	EXPECT_ERROR(VIEW "plane 0 0 0 0 -0.0e-400 0\n", 8, "plane: the normal is zero");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 0 2", "45", "32 24"), 1,
		     "view: 'up' is zero or parallel to the view direction");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 0 -1", "45", "32 24"), 1,
		     "'up' is zero or parallel");
	EXPECT_ERROR(VIEW_WITH("0 0 -10", "0 0 0", "0 0 0", "45", "32 24"), 1,
		     "'up' is zero or parallel");
	EXPECT_ERROR("b 0 0 0\n" VIEW_WITH("0 0 -10", "0 0 0", "0 0 1", "45", "32 24"), 2,
		     "'up' is zero or parallel");
	/* up need not be perpendicular to the view (SPD's tetra). */
	EXPECT_OK(VIEW_WITH("1 1 1", "0 0 0", "0 0 1", "45", "32 24"));
}

static void test_bad_bytes(void)
{
	char text[512];
	size_t n;
	EXPECT_ERROR(VIEW "sphere 0 0 0 1\n", 8, "unknown command 'sphere'");
	CHECK_STR(messages, "rt: " FILE_NAME ":8: unknown command 'sphere'\n");
	EXPECT_ERROR(VIEW "S 0 0 0 1\n", 8, "unknown command 'S'");
	EXPECT_ERROR("0.5 0.5\n", 1, "unknown command '0.5'");

	/* NUL bytes and binary files: named by value, at their line. */
	EXPECT_ERROR(VIEW "s 0 0 0\0 1\n", 8,
		     "unexpected byte 0x00 (this is not a text scene file)");
	EXPECT_ERROR("\0", 1, "unexpected byte 0x00");
	EXPECT_ERROR("\x89PNG\r\n\x1A\n\0\0\0\rIHDR", 1, "unexpected byte 0x89");
	EXPECT_ERROR(VIEW "s 0 0 0 1\x01\n", 8, "unexpected byte 0x01");
	EXPECT_ERROR(VIEW "s 0 0 0 caf\xC3\xA9\n", 8, "unexpected byte 0xC3");
	EXPECT_ERROR(VIEW "\x7F\n", 8, "unexpected byte 0x7F");

	/* Byte-order marks: UTF-16 either way round is refused at line 1. */
	EXPECT_ERROR("\xFF\xFEv\0\n\0", 1, "the file is UTF-16 text; save it as ASCII or UTF-8");
	EXPECT_ERROR("\xFE\xFF\0v\0\n", 1, "the file is UTF-16 text");
	EXPECT_ERROR("\xEF\xBB" VIEW, 1, "unexpected bytes at the start of the file");
	EXPECT_ERROR("\xFFv\n", 1, "unexpected byte 0xFF");
	EXPECT_ERROR("\xFE\n\n", 1, "unexpected byte 0xFE");

	/* Tokens: RT_TOKEN_MAX bytes is fine, one more is an error. */
	memcpy(text, VIEW "s 0 0 0 ", sizeof VIEW "s 0 0 0 " - 1);
	n = sizeof VIEW "s 0 0 0 " - 1;
	text[n++] = '1';
	text[n++] = '.';
	while (n < sizeof VIEW "s 0 0 0 " - 1 + RT_TOKEN_MAX)
		text[n++] = '0';
	text[n] = '\0';
	CHECK_INT(parse_bytes(text, n), 1);
	CHECK_INT(message_count, 0);
	CHECK_REAL(sc.objects[0].u.sphere.radius, 1, 0);
	text[n++] = '0';
	text[n++] = '\n';
	text[n] = '\0';
	expect_message(text, n, 0, 8,
		       "token too long (over " STR(RT_TOKEN_MAX) " bytes): '1.00000000000000...'",
		       __LINE__);
	/* A very long word as a command. */
	n = 0;
	while (n < 400)
		text[n++] = 'x';
	text[n] = '\0';
	expect_message(text, n, 0, 1, "token too long", __LINE__);
}

static void test_capacities(void)
{
	static char text[sizeof VIEW + 16 * (RT_MAX_LIGHTS + 1)];
	size_t n = sizeof VIEW - 1;
	int i;
	char line[64];
	memcpy(text, VIEW, n);
	for (i = 0; i <= RT_MAX_LIGHTS; i++) {
		snprintf(line, sizeof line, "l %d 0 0\n", i);
		memcpy(text + n, line, strlen(line));
		n += strlen(line);
	}
	text[n] = '\0';
	expect_message(text, n, 0, 8 + RT_MAX_LIGHTS,
		       "too many lights: the limit is RT_MAX_LIGHTS = " STR(RT_MAX_LIGHTS)
		       " (raise it in src/config.h)",
		       __LINE__);
	/* Exactly at the capacity is fine, and each gets 1/sqrt(N). */
	CHECK_INT(parse_bytes(text, n - strlen(line)), 1);
	CHECK_INT(sc.light_count, RT_MAX_LIGHTS);
	CHECK_REAL(sc.lights[RT_MAX_LIGHTS - 1].color.y, 1 / sqrt((double)RT_MAX_LIGHTS), EPS);
}

static void test_file(void)
{
	static const char prefix[] = "rt: no-such-directory/none.nff: cannot open";
	messages[0] = '\0';
	message_count = 0;
	diag_set_sink(capture, NULL);
	CHECK_INT(load_scene_file(&sc, "no-such-directory/none.nff"), 0);
	diag_set_sink(NULL, NULL);
	CHECK_INT(message_count, 1);
	CHECK(strncmp(messages, prefix, sizeof prefix - 1) == 0);
}

#if !REAL_FIXED
/* Short decimals are read without strtod (realtext.h): 200,000 random tokens of every
 * form (signs, leading and trailing zeros, a point anywhere or none, exponents, and too
 * many digits for the short way) must read bit for bit as strtod reads them, and most
 * must take the short way. */
static void test_short_decimals(void)
{
	static char token[64];
	int i, same = 0, short_way = 0;
	test_seed(18);
	for (i = 0; i < 200000; i++) {
		int digits = 1 + (int)test_random_range(0.0, 19.99), point = (int)test_random_range(
										 -1.0, digits + 0.99);
		int at = 0, k;
		real fast = REAL_C(0.0), slow;
		char *end;
		if (test_random() < 0.3)
			token[at++] = test_random() < 0.5 ? '-' : '+';
		for (k = 0; k < digits; k++) {
			if (k == point)
				token[at++] = '.';
			token[at++] = (char)('0' + (int)test_random_range(0.0, 9.99) *
							 (test_random() < 0.2 ? 0 : 1));
		}
		if (point == digits)
			token[at++] = '.';
		if (test_random() < 0.3)
			at += snprintf(token + at, sizeof token - (size_t)at, "e%d",
				       (int)test_random_range(-40.0, 40.0));
		token[at] = '\0';
		slow = real_parse(token, &end);
		if (real_from_short_decimal(token, &fast)) {
			short_way++;
			/* Equal values, and zeros of the same sign (memcmp would see long
			 * double's padding bytes). */
			same += fast == slow && !signbit(fast) == !signbit(slow);
		} else {
			same++;
		}
	}
	CHECK_INT(same, 200000);
	CHECK(short_way > 50000);
}
#endif

void suite_parse(void)
{
	test_view();
	test_background();
	test_lights();
	test_materials();
	test_sphere();
	test_polygon();
	test_patch();
	test_cone();
	test_settings();
	test_absorb();
	test_plane();
	test_box();
	test_polyhedron();
	test_unusual_valid();
	test_numbers();
	test_polygon_counts();
	test_view_errors();
	test_bad_bytes();
	test_capacities();
	test_file();
#if !REAL_FIXED
	test_short_decimals();
#endif
}
