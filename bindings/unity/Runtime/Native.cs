// The C ABI of coulomb-hands (crates/coulomb-hands-c/include/coulomb_hands.h), one
// declaration per function, and its structs, blittable and laid out as C lays them out.
// Nothing here decides anything: World.cs turns statuses into exceptions.
using System;
using System.Runtime.InteropServices;

namespace CoulombHands
{
    /// <summary>A call's outcome (ChStatus).</summary>
    public enum Status
    {
        Ok = 0,
        NullPointer = 1,
        InvalidArgument = 2,
        BufferTooSmall = 3,
        StaleHandle = 4,
        InvalidInput = 5,
        Refused = 6,
        AbiMismatch = 7,
        Internal = 8,
    }

    /// <summary>Three numbers by value (ChVec3): a position, a size.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vec3
    {
        public float X, Y, Z;
        public Vec3(float x, float y, float z) { X = x; Y = y; Z = z; }
    }

    /// <summary>A rotation by value, x, y, z, w (ChQuat).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Quat
    {
        public float X, Y, Z, W;
        public Quat(float x, float y, float z, float w) { X = x; Y = y; Z = z; W = w; }
        public static readonly Quat Identity = new Quat(0, 0, 0, 1);
    }

    /// <summary>An object's state as the host has it (ChHostBody): the world's frame and
    /// units (<see cref="World.SetFrame"/>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct HostBody
    {
        public float PositionX, PositionY, PositionZ;
        public float RotationX, RotationY, RotationZ, RotationW;
        public float LinvelX, LinvelY, LinvelZ;
        public float AngvelX, AngvelY, AngvelZ;
        public float Mass;
        public float CenterOfMassX, CenterOfMassY, CenterOfMassZ;
        public float InertiaX, InertiaY, InertiaZ;
        public float InertiaRotationX, InertiaRotationY, InertiaRotationZ, InertiaRotationW;
    }

    /// <summary>The hands' force and torque on one object in a host step (ChWrench).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Wrench
    {
        public uint Object;
        public float ForceX, ForceY, ForceZ;
        public float TorqueX, TorqueY, TorqueZ;
        public byte Touched;
        public byte Pushed;
    }

    /// <summary>An object's state after a step (ChObjectState).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ObjectState
    {
        public float PositionX, PositionY, PositionZ;
        public float RotationX, RotationY, RotationZ, RotationW;
        public float LinvelX, LinvelY, LinvelZ;
        public float AngvelX, AngvelY, AngvelZ;
        public float HandForceX, HandForceY, HandForceZ;
        public byte Present;
        public byte Sleeping;
    }

    /// <summary>One contact of a hand on an object (ChContact).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Contact
    {
        public uint Object, Hand, Bone, State;
        public float PointX, PointY, PointZ;
        public float NormalX, NormalY, NormalZ;
        public float BonePointX, BonePointY, BonePointZ;
        public float ForceX, ForceY, ForceZ;
        public float Depth, NormalForce, Stiffness;
    }

    /// <summary>The C functions. Texts are NUL-terminated UTF-8 byte arrays.</summary>
    public static class Native
    {
#if UNITY_IOS && !UNITY_EDITOR
        public const string Library = "__Internal";
#else
        public const string Library = "coulomb_hands_c";
#endif

        /// <summary>The header's CH_ABI_VERSION this layer was written for.</summary>
        public const uint AbiVersion = 1;

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern uint ch_abi_version();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_check_abi(uint version);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_last_error(byte[] message, UIntPtr len, out UIntPtr needed);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_new(byte[] method, byte[] configJson, out WorldHandle world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_free(IntPtr world);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_set_frame(WorldHandle world, byte[] frame);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_add_ground(WorldHandle world, float height, float friction);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_add_box(WorldHandle world, byte[] name, Vec3 size, float mass, Vec3 position, Quat rotation, byte[] material, out uint id);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_add_sphere(WorldHandle world, byte[] name, float radius, float mass, Vec3 position, byte[] material, out uint id);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_add_scene(WorldHandle world, byte[] sceneJson, byte[] dir, out uint first, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_add_hand(WorldHandle world, byte[] side, out uint hand);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_set_hand_joints(WorldHandle world, uint hand, byte[] layout, float[] positions, UIntPtr positionsLen, float[] radii, UIntPtr radiiLen, float[] orientations, UIntPtr orientationsLen);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_clear_hand(WorldHandle world, uint hand);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_step(WorldHandle world, uint steps);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_time(WorldHandle world, out double time);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_object_count(WorldHandle world, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_object_states(WorldHandle world, [Out] ObjectState[] states, UIntPtr len, out UIntPtr needed);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_contacts(WorldHandle world, [Out] Contact[] contacts, UIntPtr len, out UIntPtr needed);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_set_host_bodies(WorldHandle world, uint[] ids, HostBody[] bodies, UIntPtr count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_world_host_step(WorldHandle world, [Out] Wrench[] wrenches, UIntPtr len, out UIntPtr written);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)] public static extern Status ch_replay(byte[] path, byte[] json, UIntPtr len, out UIntPtr needed);
    }

    /// <summary>A world's handle, freed once by <c>ch_world_free</c> when disposed or
    /// finalised.</summary>
    public sealed class WorldHandle : SafeHandle
    {
        public WorldHandle() : base(IntPtr.Zero, true) { }

        public override bool IsInvalid { get { return handle == IntPtr.Zero; } }

        protected override bool ReleaseHandle()
        {
            return Native.ch_world_free(handle) == Status.Ok;
        }
    }
}
