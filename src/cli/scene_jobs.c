/* What every program makes of the scene options: the settings of an image
 * (its tile's and the viewer's canonical text, --stats) and the render
 * job they ask for, written once for whitted, the page and the viewer. */
#include "cli/scene_opts.h"

void cli_settings(struct settings *out, const struct cli_scene *o, const struct scene *s,
		  const struct camera_params *cam)
{
	settings_init(out);
	out->size = scene_image_size(s);
	out->recursion = scene_recursion(s);
	out->camera = *cam;
	out->floor = !o->no_floor;
	out->floor_width = o->floor_width;
	out->floor_tile = o->floor_tile;
	out->floor_mat = o->floor_mat;
	out->floor_from_view = !o->floor_given;
	out->dialect = o->read.dialect;
	out->clamp = o->clamp;
	out->samples = o->samples;
	out->floor_texture[0] = o->floor_texture[0];
	out->floor_texture[1] = o->floor_texture[1];
	out->glass = o->glass_text;
	out->floor_texture_hash = scene_floor_texture_hash(s);
}

void cli_render_job(struct render_job *job, const struct cli_scene *o, const struct scene *s,
		    const struct camera *cam, int threads, uint64_t max_rays)
{
	render_job_init(job, s, cam, threads);
	job->settings.clamp = o->clamp;
	job->samples = o->samples;
	job->max_rays = max_rays;
}
