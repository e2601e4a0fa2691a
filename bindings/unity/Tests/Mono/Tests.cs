// The package's tests, compiled with mcs and run under Mono (crates/coulomb-hands-c/tests/
// mono.rs runs them in the test suite): the pinch of the C tests through both modes, the
// second through Rig in Unity's frame, as CoulombHandsRig drives it; the sample scene; and
// bad input as typed exceptions that change nothing.
using System;
using CoulombHands;

static class Tests
{
    const float Dt = 1.0f / 90.0f, Side = 0.03f, Table = 0.485f, Squeeze = 0.008f, Lift = 0.1f;
    const int Steps = 135; // 1.5 s
    static int failures;

    static void Check(bool ok, string what)
    {
        Console.WriteLine((ok ? "ok   " : "FAIL ") + what);
        if (!ok) failures++;
    }

    static void Throws<E>(Action call, string named, string what) where E : Exception
    {
        try
        {
            call();
            Check(false, what + ": no exception");
        }
        catch (E e)
        {
            Check(e.Message.Contains(named), what + ": " + typeof(E).Name + ": " + e.Message);
        }
        catch (Exception e)
        {
            Check(false, what + ": " + e.GetType().Name + " instead of " + typeof(E).Name + ": " + e.Message);
        }
    }

    /// A hand of 26 OpenXR joints, palm down, its straight index finger pointing along x at
    /// the box with its tip at tipX; the other fingers hang below their knuckles.
    static float[] PinchHand(int side, float tipX, float y, float z)
    {
        var j = new float[78];
        float dir = -side;
        float[] tip = { tipX, y, z }, wrist = { tipX - dir * 0.165f, y, z };
        Action<int, float[], float, float, float> put = (k, at, f, down, lateral) =>
        {
            j[3 * k] = at[0] + f; j[3 * k + 1] = at[1] - down; j[3 * k + 2] = at[2] + lateral;
        };
        put(0, wrist, dir * 0.085f, 0, -0.03f);
        put(1, wrist, 0, 0, -0.02f);
        put(2, wrist, dir * 0.02f, 0, 0.02f);
        put(3, wrist, dir * 0.05f, 0, 0.04f);
        put(4, wrist, dir * 0.08f, 0, 0.055f);
        put(5, wrist, dir * 0.10f, 0, 0.065f);
        put(6, wrist, dir * 0.01f, 0, 0);
        put(7, tip, -dir * 0.085f, 0, 0);
        put(8, tip, -dir * 0.045f, 0, 0);
        put(9, tip, -dir * 0.022f, 0, 0);
        put(10, tip, 0, 0, 0);
        for (int k = 1; k <= 3; k++)
        {
            int b = 6 + 5 * k;
            float lateral = -0.021f * k;
            put(b, wrist, dir * 0.01f, 0, lateral);
            put(b + 1, tip, -dir * 0.085f, 0, lateral);
            put(b + 2, tip, -dir * 0.085f, 0.035f, lateral);
            put(b + 3, tip, -dir * 0.085f, 0.06f, lateral);
            put(b + 4, tip, -dir * 0.085f, 0.08f, lateral);
        }
        return j;
    }

    static float[] Radii()
    {
        var r = new float[26];
        for (int k = 2; k < 26; k++) r[k] = 0.008f;
        return r;
    }

    /// Fingertip depth and lift at time t: close over 0.3 s, wait, lift along a
    /// minimum-jerk path in 0.5 s.
    static void Motion(float t, out float depth, out float up)
    {
        depth = t < 0.3f ? -0.01f + (0.01f + Squeeze) * t / 0.3f : Squeeze;
        float u = t < 0.4f ? 0 : t < 0.9f ? (t - 0.4f) / 0.5f : 1;
        up = Lift * u * u * u * (10 - 15 * u + 6 * u * u);
    }

    static float BuiltIn(float mass)
    {
        using (var world = new World(null, "{\"dt\": 0.011111111}"))
        {
            world.AddGround(Table, 0.5f);
            world.AddBox("box", new Vec3(Side, Side, Side), mass, new Vec3(0, Table + Side / 2, 0),
                         Quat.Identity, "wood");
            uint[] hands = { world.AddHand("left"), world.AddHand("right") };
            for (int s = 0; s < Steps; s++)
            {
                float depth, up;
                Motion(s * Dt, out depth, out up);
                for (int i = 0; i < 2; i++)
                {
                    int side = i == 0 ? -1 : 1;
                    world.SetHandJoints(hands[i], "openxr",
                        PinchHand(side, side * (Side / 2 - depth), Table + Side / 2 + up, 0), Radii());
                }
                world.Step();
            }
            return world.ObjectStates()[0].PositionY - (Table + Side / 2);
        }
    }

    /// The same in host mode through Rig, in Unity's frame (z mirrored: the scene is
    /// placed at z = -0.2 there), with XR Hands' joint order (wrist before palm), the box
    /// integrated here by semi-implicit Euler on a table.
    static float Hosted(float mass)
    {
        const float z = -0.2f;
        using (var rig = new Rig(Dt))
        {
            float inertia = mass * Side * Side / 6;
            rig.AddBox("box", new Vec3(Side, Side, Side), mass, new Vec3(0, Table + Side / 2, z),
                       Quat.Identity, "wood");
            var b = new HostBody
            {
                PositionY = Table + Side / 2, PositionZ = z, RotationW = 1, Mass = mass,
                InertiaX = inertia, InertiaY = inertia, InertiaZ = inertia, InertiaRotationW = 1,
            };
            for (int s = 0; s < Steps; s++)
            {
                float depth, up;
                Motion(s * Dt, out depth, out up);
                for (int i = 0; i < 2; i++)
                {
                    int side = i == 0 ? -1 : 1;
                    var openxr = PinchHand(side, side * (Side / 2 - depth), Table + Side / 2 + up, z);
                    // XR Hands lists the wrist first, then the palm.
                    var xr = (float[])openxr.Clone();
                    for (int k = 0; k < 3; k++) { xr[k] = openxr[3 + k]; xr[3 + k] = openxr[k]; }
                    rig.SetHand(i, xr, Radii());
                }
                var w = rig.Step(new[] { b })[0];
                b.LinvelX += w.ForceX / mass * Dt;
                b.LinvelY += (w.ForceY / mass - 9.81f) * Dt;
                b.LinvelZ += w.ForceZ / mass * Dt;
                if (b.PositionY - Side / 2 <= Table + 1e-6f && b.LinvelY <= 0)
                    b.LinvelX = b.LinvelY = b.LinvelZ = 0; // resting on the table
                b.PositionX += b.LinvelX * Dt;
                b.PositionY = Math.Max(b.PositionY + b.LinvelY * Dt, Table + Side / 2);
                b.PositionZ += b.LinvelZ * Dt;
            }
            return b.PositionY - (Table + Side / 2);
        }
    }

    static void Pinches()
    {
        float light = 0.04f, heavy = 0.45f;
        float rise = BuiltIn(light);
        Check(rise > Lift - 0.01f, "built-in: the pinch lifts 0.04 kg (rose " + rise + " m)");
        rise = BuiltIn(heavy);
        Check(rise < 0.01f, "built-in: 0.45 kg slips out (rose " + rise + " m)");
        rise = Hosted(light);
        Check(rise > Lift - 0.01f, "hosted, Unity frame: lifts 0.04 kg (rose " + rise + " m)");
        rise = Hosted(heavy);
        Check(rise < 0.01f, "hosted, Unity frame: 0.45 kg slips out (rose " + rise + " m)");
    }

    static void SampleScene(string dir)
    {
        using (var world = new World())
        {
            var text = System.IO.File.ReadAllText(System.IO.Path.Combine(dir, "scene.json"));
            var ids = world.AddScene(text, dir);
            Check(ids.Length == 1, "the sample scene adds its cube (" + ids.Length + ")");
            world.Step(100);
            var cube = world.ObjectStates()[0];
            Check(Math.Abs(cube.PositionY - 0.775f) < 0.002f, "the cube rests on the table (y " + cube.PositionY + ")");
        }
    }

    static void BadInput()
    {
        Throws<InvalidInputException>(() => new World(null, "{\"dt\": 0.001,"), "config_json", "bad config JSON");
        Throws<InvalidArgumentException>(() => new World("grip"), "method", "unknown method");
        using (var world = new World())
        {
            world.SetFrame("unity");
            Throws<InvalidArgumentException>(() => world.SetFrame("blender"), "frame", "unknown frame");
            Vec3 size = new Vec3(0.05f, 0.05f, 0.05f), at = new Vec3(0, 0.3f, 0);
            Throws<NullArgumentException>(() => world.AddBox(null, size, 0.1f, at, Quat.Identity), "name", "a null name");
            Throws<RefusedException>(() => world.AddBox("b", new Vec3(0.05f, 0, 0.05f), 0.1f, at, Quat.Identity), "half_extents.y", "a flat box");
            Throws<InvalidArgumentException>(() => world.AddBox("b", size, 0.1f, new Vec3(0, float.NaN, 0), Quat.Identity), "position[1]", "a NaN position");
            Throws<InvalidArgumentException>(() => world.AddBox("b", size, 0.1f, at, new Quat(0, 0, 0, 0)), "rotation", "a zero rotation");
            Throws<RefusedException>(() => world.AddBox("b", size, -1f, at, Quat.Identity), "mass", "a negative mass");
            Throws<InvalidArgumentException>(() => world.AddBox("b", size, 0.1f, at, Quat.Identity, "velvet"), "velvet", "an unknown material");
            Throws<RefusedException>(() => world.AddSphere("s", -0.02f, 0.1f, at), "radius", "a negative radius");
            Check(world.ObjectCount == 0, "no object was added");
            uint box = world.AddBox("b", size, 0.1f, at, Quat.Identity);
            uint hand = world.AddHand("right");
            Throws<InvalidArgumentException>(() => world.SetHandJoints(hand, "openxr", new float[75]), "positions", "25 joints for openxr");
            Throws<RefusedException>(() => world.SetHandJoints(hand + 5, "openxr", PinchHand(1, 0.3f, 0.3f, 0)), "hand", "an unknown hand");
            world.Step(2);
            var before = world.ObjectStates()[0];
            var good = new HostBody { PositionY = 0.2f, RotationW = 1, Mass = 0.1f, InertiaX = 4e-5f, InertiaY = 4e-5f, InertiaZ = 4e-5f, InertiaRotationW = 1 };
            var bad = good;
            bad.AngvelY = float.PositiveInfinity;
            Throws<InvalidArgumentException>(() => world.SetHostBodies(new[] { box, box }, new[] { good, bad }), "bodies[1]", "an infinite angular velocity");
            bad = good;
            bad.InertiaZ = 0;
            Throws<RefusedException>(() => world.SetHostBodies(new[] { box, box }, new[] { good, bad }), "inertia", "a zero inertia");
            Throws<RefusedException>(() => world.SetHostBodies(new[] { box, 9u }, new[] { good, good }), "9", "an unknown object");
            Throws<InvalidArgumentException>(() => world.SetHostBodies(new[] { box }, new[] { good, good }), "ids", "two bodies for one id");
            var after = world.ObjectStates()[0];
            Check(before.PositionY == after.PositionY && before.LinvelY == after.LinvelY, "the refused calls left the box where it was");
            Throws<InvalidInputException>(() => World.Replay("data/leap/missing.json.lz"), "missing.json.lz", "a missing recording");
            world.Dispose();
            Throws<ObjectDisposedException>(() => world.Step(), "", "a disposed world");
        }
    }

    static int Main(string[] args)
    {
        // The layer's structs as C lays them out (the sizes the test runner passes).
        Check(System.Runtime.InteropServices.Marshal.SizeOf(typeof(HostBody)) == int.Parse(args[0]), "HostBody's size is C's");
        Check(System.Runtime.InteropServices.Marshal.SizeOf(typeof(Wrench)) == int.Parse(args[1]), "Wrench's size is C's");
        Check(System.Runtime.InteropServices.Marshal.SizeOf(typeof(ObjectState)) == int.Parse(args[2]), "ObjectState's size is C's");
        Check(System.Runtime.InteropServices.Marshal.SizeOf(typeof(Contact)) == int.Parse(args[3]), "Contact's size is C's");
        Pinches();
        SampleScene(args[4]);
        BadInput();
        Console.WriteLine(failures == 0 ? "all passed" : failures + " failed");
        return failures == 0 ? 0 : 1;
    }
}
