package ray.grading.worker;

import java.util.ArrayList;
import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.bvh.BoundingBoxes;
import ray.bvh.Box;
import ray.bvh.BvhNode;
import ray.bvh.BvhTree;
import ray.camera.Camera;
import ray.grading.wire.Protocol;
import ray.grading.wire.Records;
import ray.grading.wire.ThrownData;
import ray.grading.wire.Trees;
import ray.grading.wire.WireError;
import ray.grading.wire.WireIn;
import ray.grading.wire.WireOut;
import ray.math.Vec3;
import ray.render.SceneTracer;
import ray.shading.Brdf;
import ray.shading.BrdfShader;
import ray.shading.DirectLighting;
import ray.shading.Fresnel;
import ray.shading.Light;
import ray.shading.MicrofacetDistribution;
import ray.shading.Shader;
import ray.shading.Texture;
import ray.surface.Surface;

/**
 * Runs one call of the judge's on a twin and writes its answer: what the student's method returned
 * and what it changed (of the record and the ray), or what it threw. The call's arguments are read
 * whole before the student's code runs; what the student's code does cannot reach this class's own
 * parsing, and a message this class cannot parse ends the worker.
 */
final class WorkerCalls {
    private final WorkerObjects objects;
    private final JudgeLink link;

    WorkerCalls(WorkerObjects objects, JudgeLink link) {
        this.objects = objects;
        this.link = link;
    }

    /** A CALL message: its definitions, then one call; the answer. */
    WireOut call(WireIn in) {
        objects.define(in);
        WireOut answer = new WireOut();
        try {
            objects.settle();
            int op = in.u8();
            switch (op) {
                case Protocol.OP_INTERSECT:
                    intersect(in, answer);
                    break;
                case Protocol.OP_GENERATE_RAY:
                    generateRay(in, answer);
                    break;
                case Protocol.OP_TEX_COLOR:
                    texColor(in, answer);
                    break;
                case Protocol.OP_SHADE:
                    shade(in, answer);
                    break;
                case Protocol.OP_SHADE_RAY:
                    shadeRay(in, answer);
                    break;
                case Protocol.OP_BRDF_VALUE:
                    brdfValue(in, answer);
                    break;
                case Protocol.OP_MICROFACET_D:
                case Protocol.OP_MICROFACET_G1:
                case Protocol.OP_FRESNEL:
                    microfacetTerm(op, in, answer);
                    break;
                case Protocol.OP_BOX_OF_SPHERE:
                case Protocol.OP_BOX_OF_TRIANGLE:
                case Protocol.OP_BOX_OF_CYLINDER:
                case Protocol.OP_BOX_HIT:
                    boxCall(op, in, answer);
                    break;
                case Protocol.OP_TREE_BUILD:
                    treeBuild(in, answer);
                    break;
                case Protocol.OP_TREE_CLOSEST:
                case Protocol.OP_TREE_ANY:
                    treeSearch(op, in, answer);
                    break;
                default:
                    throw new WireError("a call of kind " + op);
            }
        } catch (WorkerObjects.BrokenTwin b) {
            threw(answer, b.why);
        }
        return answer;
    }

    /** The twin a call names: its first bytes. */
    private int target(WireIn in) {
        int kind = in.u8();
        if (kind != Protocol.REF_TWIN) {
            throw new WireError("a call on an object named by kind " + kind);
        }
        return in.i32();
    }

    private void intersect(WireIn in, WireOut answer) {
        int handle = target(in);
        Ray ray = Records.readRay(in);
        IntersectionRecord out = new IntersectionRecord();
        Records.read(in, out, objects);
        in.end();
        intersect(objects.twin(handle, Surface.class), out, ray, answer);
    }

    /** Runs intersect on the twin and writes its answer: returned, the record's and the ray's changes; or what it threw. */
    void intersect(Surface twin, IntersectionRecord out, Ray ray, WireOut answer) {
        IntersectionRecord before = new IntersectionRecord();
        before.set(out);
        double start = ray.start;
        double end = ray.end;
        boolean hit;
        try {
            hit = twin.intersect(out, ray);
        } catch (Throwable t) { // whatever the student's code throws is its answer
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED).bool(hit);
        Records.writeChanges(answer, Records.changes(before, out), out, objects);
        Records.writeRayChanges(answer, Records.rayChanges(start, end, ray), ray);
    }

    private void generateRay(WireIn in, WireOut answer) {
        int handle = target(in);
        double u = in.f64();
        double v = in.f64();
        in.end();
        generateRay(objects.twin(handle, Camera.class), u, v, answer);
    }

    void generateRay(Camera camera, double u, double v, WireOut answer) {
        Ray ray;
        try {
            ray = camera.generateRay(u, v);
        } catch (Throwable t) {
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED);
        Records.writeRayOrNull(answer, ray);
    }

    private void texColor(WireIn in, WireOut answer) {
        int handle = target(in);
        double u = in.f64();
        double v = in.f64();
        in.end();
        texColor(objects.twin(handle, Texture.class), u, v, answer);
    }

    void texColor(Texture texture, double u, double v, WireOut answer) {
        Vec3 color;
        try {
            color = texture.getTexColor(u, v);
        } catch (Throwable t) {
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED).vec(color);
    }

    private void shade(WireIn in, WireOut answer) {
        int handle = target(in);
        IntersectionRecord hit = new IntersectionRecord();
        Records.read(in, hit, objects);
        Ray ray = Records.readRay(in);
        int depth = in.i32();
        int count = in.count(Protocol.MAX_LIGHTS, "lights");
        List<Light> lights = new ArrayList<>(count);
        for (int k = 0; k < count; k++) {
            lights.add(new Light(in.vec(), in.vec()));
        }
        Vec3 textureColor = in.vec();
        in.end();
        Shader twin = objects.twin(handle, Shader.class);
        Vec3 color;
        try {
            // The texture stayed on the judge's side, which sent its color at this hit; so did a 2019
            // shader's BRDF, whose values are asked of the judge.
            Texture given = textureColor == null ? null : new GivenColor(textureColor);
            if (twin instanceof DirectLighting) {
                ((DirectLighting) twin).setTexture(given);
            } else if (twin instanceof BrdfShader) {
                ((BrdfShader) twin).setTexture(given);
                ((BrdfShader) twin).setBrdf(new JudgeBrdf(link, "the judge's BRDF"));
            }
            color = twin.shade(hit, ray, new JudgeShading(lights, hit, link, objects), depth);
        } catch (Throwable t) {
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED).vec(color);
    }

    private void shadeRay(WireIn in, WireOut answer) {
        int handle = target(in);
        Ray ray = Records.readRay(in);
        int depth = in.i32();
        in.end();
        SceneTracer twin = objects.twin(handle, SceneTracer.class);
        Vec3 color;
        try {
            // The hits are shaded on the judge's side, which holds the shaders, lights and the rest of the scene.
            twin.use(twin.surfaces(), twin.backgroundColor(), new JudgeHits(link, objects), twin.maxDepth());
            color = twin.shadeRay(ray, depth);
        } catch (Throwable t) {
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED).vec(color);
    }

    private void brdfValue(WireIn in, WireOut answer) {
        int handle = target(in);
        Vec3 rhoD = in.vec();
        Vec3 n = in.vec();
        Vec3 l = in.vec();
        Vec3 v = in.vec();
        in.end();
        Brdf twin = objects.twin(handle, Brdf.class);
        Vec3 value;
        try {
            value = twin.value(rhoD, n, l, v);
        } catch (Throwable t) {
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED).vec(value);
    }

    /** D, G1 or F of the student's microfacet BRDF: a number of the twin's, from vectors or a cosine. */
    private void microfacetTerm(int op, WireIn in, WireOut answer) {
        int handle = target(in);
        double value;
        if (op == Protocol.OP_FRESNEL) {
            double cosine = in.f64();
            in.end();
            Fresnel twin = objects.twin(handle, Fresnel.class);
            try {
                value = twin.reflectance(cosine);
            } catch (Throwable t) {
                threw(answer, t);
                return;
            }
        } else {
            Vec3 x = op == Protocol.OP_MICROFACET_G1 ? in.vec() : null;
            Vec3 n = in.vec();
            Vec3 h = in.vec();
            in.end();
            MicrofacetDistribution twin = objects.twin(handle, MicrofacetDistribution.class);
            try {
                value = op == Protocol.OP_MICROFACET_G1 ? twin.masking(x, n, h) : twin.normalDistribution(n, h);
            } catch (Throwable t) {
                threw(answer, t);
                return;
            }
        }
        answer.u8(Protocol.RETURNED).f64(value);
    }

    /** A box of the student's BoundingBoxes (of a sphere, a triangle or a cylinder), or its slab test of a box. */
    private void boxCall(int op, WireIn in, WireOut answer) {
        int handle = target(in);
        BoundingBoxes twin;
        Object result;
        if (op == Protocol.OP_BOX_OF_SPHERE) {
            Vec3 center = in.vec();
            double radius = in.f64();
            in.end();
            twin = objects.twin(handle, BoundingBoxes.class);
            try {
                result = twin.ofSphere(center, radius);
            } catch (Throwable t) {
                threw(answer, t);
                return;
            }
        } else if (op == Protocol.OP_BOX_OF_CYLINDER) {
            Vec3 center = in.vec();
            double radius = in.f64();
            double height = in.f64();
            in.end();
            twin = objects.twin(handle, BoundingBoxes.class);
            try {
                result = twin.ofCylinder(center, radius, height);
            } catch (Throwable t) {
                threw(answer, t);
                return;
            }
        } else if (op == Protocol.OP_BOX_OF_TRIANGLE) {
            Vec3 a = in.vec();
            Vec3 b = in.vec();
            Vec3 c = in.vec();
            in.end();
            twin = objects.twin(handle, BoundingBoxes.class);
            try {
                result = twin.ofTriangle(a, b, c);
            } catch (Throwable t) {
                threw(answer, t);
                return;
            }
        } else {
            Box box = Trees.readBox(in);
            Ray ray = Records.readRay(in);
            in.end();
            twin = objects.twin(handle, BoundingBoxes.class);
            try {
                result = twin.hit(box, ray);
            } catch (Throwable t) {
                threw(answer, t);
                return;
            }
        }
        answer.u8(Protocol.RETURNED);
        if (result instanceof Boolean) {
            answer.bool((Boolean) result);
        } else {
            Trees.writeBox(answer, (Box) result);
        }
    }

    /** The student's build over the twin's boxes: the order it left and the tree it returned. */
    private void treeBuild(WireIn in, WireOut answer) {
        int handle = target(in);
        int start = in.i32();
        int end = in.i32();
        in.end();
        BvhTree twin = objects.twin(handle, BvhTree.class);
        WireOut tree = new WireOut();
        int[] order;
        try {
            BvhNode root = twin.build(start, end);
            order = Trees.order(twin);
            // Written here, so that a tree with a cycle (made by reflection) is what the student's code threw.
            Trees.writeTree(tree, root);
        } catch (Throwable t) {
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED);
        answer.i32(order == null ? -1 : order.length);
        if (order != null) {
            for (int value : order) {
                answer.i32(value);
            }
        }
        answer.raw(tree);
    }

    /** The student's closest-hit or any-hit search from a node the judge sent, with the box tests it made (the judge counts the primitive tests). */
    private void treeSearch(int op, WireIn in, WireOut answer) {
        int handle = target(in);
        BvhNode node = objects.node(in.i32());
        Ray ray = Records.readRay(in);
        IntersectionRecord out = new IntersectionRecord();
        if (op == Protocol.OP_TREE_CLOSEST) {
            Records.read(in, out, objects);
        }
        in.end();
        BvhTree twin = objects.twin(handle, BvhTree.class);
        twin.resetCounts();
        IntersectionRecord before = new IntersectionRecord();
        before.set(out);
        double start = ray.start;
        double end = ray.end;
        boolean hit;
        try {
            hit = op == Protocol.OP_TREE_CLOSEST ? twin.closestHit(node, out, ray) : twin.anyHit(node, ray);
        } catch (Throwable t) {
            threw(answer, t);
            return;
        }
        answer.u8(Protocol.RETURNED).bool(hit);
        if (op == Protocol.OP_TREE_CLOSEST) {
            Records.writeChanges(answer, Records.changes(before, out), out, objects);
            Records.writeRayChanges(answer, Records.rayChanges(start, end, ray), ray);
        }
        answer.i64(twin.boxesTested());
    }

    /** What the student's code threw; a judge-side surface's exception, or a broken twin's, passes on as it was. */
    static void threw(WireOut answer, Throwable t) {
        threw(answer, thrownData(t));
    }

    static ThrownData thrownData(Throwable t) {
        if (t instanceof JudgeSurface.JudgeSideThrew) {
            return ((JudgeSurface.JudgeSideThrew) t).thrown;
        }
        if (t instanceof WorkerObjects.BrokenTwin) {
            return ((WorkerObjects.BrokenTwin) t).why;
        }
        return ThrownData.of(t, WorkerMain.OWN_PACKAGE);
    }

    static void threw(WireOut answer, ThrownData thrown) {
        answer.u8(Protocol.THREW);
        thrown.write(answer);
    }
}
