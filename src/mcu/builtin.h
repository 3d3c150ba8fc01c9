/* builtin.h - a scene compiled into the firmware (tools/scene2c writes it), for a
 * microcontroller with no host to read a scene file from: `make mcu-builtin`.
 * See LICENSE for copyright and licence. */
#ifndef RT_BUILTIN_H
#define RT_BUILTIN_H

#include <stddef.h>

#ifndef RT_BUILTIN_SCENE
#define RT_BUILTIN_SCENE 0 /* 1: the build has a scene compiled in */
#endif

extern const char rt_builtin_scene_name[]; /* the file it came from, for messages */
extern const unsigned char rt_builtin_scene[];
extern const size_t rt_builtin_scene_size;

#endif
