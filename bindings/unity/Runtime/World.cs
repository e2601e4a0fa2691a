// A coulomb-hands world in C#: each method one C call, its status turned into a typed
// exception (Errors.cs). The library checks every argument; a failed call changes nothing.
using System;
using System.Text;

namespace CoulombHands
{
    public sealed class World : IDisposable
    {
        private readonly WorldHandle handle;

        /// <summary>Throws <see cref="AbiMismatchException"/> if the native library is not
        /// the ABI version this package was written for. The constructor calls it.</summary>
        public static void CheckAbi()
        {
            Check(Native.ch_check_abi(Native.AbiVersion));
        }

        /// <summary>A new, empty world: <paramref name="method"/> is coulomb (null),
        /// thesis, kinematic or heuristic; <paramref name="configJson"/> an
        /// InteractionConfig as JSON, as a session file holds it (null for the defaults;
        /// set "dt" to the engine's fixed step).</summary>
        public World(string method = null, string configJson = null)
        {
            CheckAbi();
            WorldHandle made;
            Check(Native.ch_world_new(Text(method), Text(configJson), out made));
            handle = made;
        }

        /// <summary>The frame and units of every later call: "library", "unity" or
        /// "unreal".</summary>
        public void SetFrame(string frame)
        {
            Check(Native.ch_world_set_frame(handle, Text(frame)));
        }

        public void AddGround(float height, float friction = 0.5f)
        {
            Check(Native.ch_world_add_ground(handle, height, friction));
        }

        /// <summary>A box of full <paramref name="size"/>; its id.</summary>
        public uint AddBox(string name, Vec3 size, float mass, Vec3 position, Quat rotation,
                           string material = null)
        {
            uint id;
            Check(Native.ch_world_add_box(handle, Text(name), size, mass, position, rotation,
                                          Text(material), out id));
            return id;
        }

        /// <summary>A ball; its id.</summary>
        public uint AddSphere(string name, float radius, float mass, Vec3 position,
                              string material = null)
        {
            uint id;
            Check(Native.ch_world_add_sphere(handle, Text(name), radius, mass, position,
                                             Text(material), out id));
            return id;
        }

        /// <summary>A scene file's JSON (the library's frame); the ids it added.</summary>
        public uint[] AddScene(string sceneJson, string dir = null)
        {
            uint first, count;
            Check(Native.ch_world_add_scene(handle, Text(sceneJson), Text(dir), out first,
                                            out count));
            var ids = new uint[count];
            for (uint i = 0; i < count; i++) ids[i] = first + i;
            return ids;
        }

        /// <summary>A hand, "left" or "right"; its id.</summary>
        public uint AddHand(string side)
        {
            uint id;
            Check(Native.ch_world_add_hand(handle, Text(side), out id));
            return id;
        }

        /// <summary>A hand's joints in <paramref name="layout"/>'s order ("openxr" 26,
        /// "webxr" 25, "mediapipe" 21): 3 values a position, 1 a radius, 4 an
        /// orientation (x, y, z, w); radii and orientations may be null.</summary>
        public void SetHandJoints(uint hand, string layout, float[] positions,
                                  float[] radii = null, float[] orientations = null)
        {
            Check(Native.ch_world_set_hand_joints(handle, hand, Text(layout), positions,
                                                  Length(positions), radii, Length(radii),
                                                  orientations, Length(orientations)));
        }

        public void ClearHand(uint hand)
        {
            Check(Native.ch_world_clear_hand(handle, hand));
        }

        /// <summary>Steps the library's own world (built-in mode).</summary>
        public void Step(uint steps = 1)
        {
            Check(Native.ch_world_step(handle, steps));
        }

        public double Time
        {
            get
            {
                double time;
                Check(Native.ch_world_time(handle, out time));
                return time;
            }
        }

        public uint ObjectCount
        {
            get
            {
                uint count;
                Check(Native.ch_world_object_count(handle, out count));
                return count;
            }
        }

        /// <summary>Every object's state, by id.</summary>
        public ObjectState[] ObjectStates()
        {
            return Fetch<ObjectState>(Native.ch_world_object_states);
        }

        /// <summary>The contacts after the last step.</summary>
        public Contact[] Contacts()
        {
            return Fetch<Contact>(Native.ch_world_contacts);
        }

        private delegate Status Query<T>(WorldHandle world, T[] into, UIntPtr len,
                                         out UIntPtr needed);

        /// <summary>An output's size queried with no array, then the output.</summary>
        private T[] Fetch<T>(Query<T> query)
        {
            UIntPtr needed;
            Check(query(handle, null, UIntPtr.Zero, out needed));
            var items = new T[(int)needed];
            Check(query(handle, items, needed, out needed));
            return items;
        }

        /// <summary>Host mode: the objects' states now, all checked before any is set.</summary>
        public void SetHostBodies(uint[] ids, HostBody[] bodies)
        {
            if (ids == null) throw new NullArgumentException("SetHostBodies: ids is null");
            if (bodies == null) throw new NullArgumentException("SetHostBodies: bodies is null");
            if (ids.Length != bodies.Length)
                throw new InvalidArgumentException(string.Format(
                    "SetHostBodies: {0} ids for {1} bodies", ids.Length, bodies.Length));
            Check(Native.ch_world_set_host_bodies(handle, ids, bodies, (UIntPtr)ids.Length));
        }

        /// <summary>Host mode: one step of the hands; each object's wrench, to apply with
        /// AddForce and AddTorque before the engine integrates.</summary>
        public Wrench[] HostStep()
        {
            var wrenches = new Wrench[ObjectCount];
            UIntPtr written;
            Check(Native.ch_world_host_step(handle, wrenches, (UIntPtr)wrenches.Length,
                                            out written));
            if ((int)written == wrenches.Length) return wrenches;
            var live = new Wrench[(int)written];
            Array.Copy(wrenches, live, live.Length);
            return live;
        }

        /// <summary>A recording replayed as the CLI's <c>replay FILE --json</c>.</summary>
        public static string Replay(string path)
        {
            UIntPtr needed;
            Check(Native.ch_replay(Text(path), null, UIntPtr.Zero, out needed));
            var json = new byte[(int)needed];
            Check(Native.ch_replay(Text(path), json, needed, out needed));
            return Encoding.UTF8.GetString(json, 0, json.Length - 1);
        }

        public void Dispose()
        {
            handle.Dispose();
        }

        /// <summary>Throws the exception of a status that is not Ok.</summary>
        private static void Check(Status status)
        {
            if (status != Status.Ok) throw CoulombHandsException.Of(status, LastError());
        }

        /// <summary>The thread's last error message.</summary>
        public static string LastError()
        {
            UIntPtr needed;
            if (Native.ch_last_error(null, UIntPtr.Zero, out needed) != Status.Ok) return "";
            var message = new byte[(int)needed];
            if (Native.ch_last_error(message, needed, out needed) != Status.Ok) return "";
            return Encoding.UTF8.GetString(message, 0, message.Length - 1);
        }

        private static byte[] Text(string s)
        {
            return s == null ? null : Encoding.UTF8.GetBytes(s + "\0");
        }

        private static UIntPtr Length(float[] values)
        {
            return (UIntPtr)(values == null ? 0 : values.Length);
        }
    }
}
