// What a Unity scene does each FixedUpdate, without UnityEngine: the bodies' states in, the
// tracked hands' joints in, one host step, the wrenches out. The component
// (Unity/CoulombHandsRig.cs) only copies Unity's values to and from these arrays, so all of
// this is compiled and tested under Mono.
using System;

namespace CoulombHands
{
    public sealed class Rig : IDisposable
    {
        /// <summary>The world; its frame is Unity's.</summary>
        public World World { get; private set; }

        private readonly uint[] hands = new uint[2];
        private uint[] ids = new uint[0];
        private readonly float[] joints = new float[3 * XrHands.JointCount];
        private readonly float[] radii = new float[XrHands.JointCount];

        /// <summary>A rig stepping at the engine's fixed step <paramref name="dt"/> (s),
        /// with <paramref name="method"/> (null: coulomb) and the config's defaults
        /// otherwise (a <see cref="CoulombHands.World"/> made directly takes any config).</summary>
        public Rig(float dt, string method = null)
        {
            var step = dt.ToString("R", System.Globalization.CultureInfo.InvariantCulture);
            World = new World(method, "{\"dt\": " + step + "}");
            World.SetFrame("unity");
            hands[0] = World.AddHand("left");
            hands[1] = World.AddHand("right");
        }

        /// <summary>A box-shaped Rigidbody the hands can touch (Unity frame, metres);
        /// its id. <see cref="Step"/>'s states follow the order bodies were added in.</summary>
        public uint AddBox(string name, Vec3 size, float mass, Vec3 position, Quat rotation,
                           string material = null)
        {
            return Added(World.AddBox(name, size, mass, position, rotation, material));
        }

        /// <summary>A sphere-shaped Rigidbody; its id.</summary>
        public uint AddSphere(string name, float radius, float mass, Vec3 position,
                              string material = null)
        {
            return Added(World.AddSphere(name, radius, mass, position, material));
        }

        private uint Added(uint id)
        {
            Array.Resize(ref ids, ids.Length + 1);
            ids[ids.Length - 1] = id;
            return id;
        }

        /// <summary>A hand's joints as Unity XR Hands gives them (XRHandJointID order, the
        /// world frame), or null when it is not tracked.</summary>
        public void SetHand(int side, float[] xrPositions, float[] xrRadii)
        {
            if (xrPositions == null)
            {
                World.ClearHand(hands[side]);
                return;
            }
            XrHands.ToOpenXr(xrPositions, xrRadii, joints, radii);
            World.SetHandJoints(hands[side], "openxr", joints, xrRadii == null ? null : radii);
        }

        /// <summary>One FixedUpdate: the bodies' states (in AddBox order), then the hands'
        /// wrenches on them, to apply with AddForce and AddTorque before the engine
        /// integrates.</summary>
        public Wrench[] Step(HostBody[] states)
        {
            World.SetHostBodies(ids, states);
            return World.HostStep();
        }

        public void Dispose()
        {
            World.Dispose();
        }
    }

    /// <summary>Unity XR Hands' joints in OpenXR's order: the same 26 joints, but XR Hands
    /// lists the wrist before the palm (XRHandJointID.Wrist is index 0).</summary>
    public static class XrHands
    {
        public const int JointCount = 26;

        public static void ToOpenXr(float[] xrPositions, float[] xrRadii, float[] positions,
                                    float[] radii)
        {
            if (xrPositions.Length != 3 * JointCount)
                throw new InvalidArgumentException(string.Format(
                    "XR Hands joints: {0} values, expected {1}", xrPositions.Length,
                    3 * JointCount));
            if (xrRadii != null && xrRadii.Length != JointCount)
                throw new InvalidArgumentException(string.Format(
                    "XR Hands radii: {0} values, expected {1}", xrRadii.Length, JointCount));
            for (int j = 0; j < JointCount; j++)
            {
                int from = j == 0 ? 1 : j == 1 ? 0 : j;
                for (int k = 0; k < 3; k++) positions[3 * j + k] = xrPositions[3 * from + k];
                if (xrRadii != null) radii[j] = xrRadii[from];
            }
        }
    }
}
