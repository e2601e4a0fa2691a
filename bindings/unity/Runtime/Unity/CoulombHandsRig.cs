// The scene's side of the rig: Unity's values copied into CoulombHands.Rig each FixedUpdate
// and its wrenches applied back. All the logic is in Rig (Runtime/Rig.cs), which is
// compiled and tested under Mono; this file needs UnityEngine and XR Hands, and was not
// compiled here (bindings/unity/README.md).
using CoulombHands;
using UnityEngine;
using UnityEngine.XR.Hands;

namespace CoulombHands.Unity
{
    public sealed class CoulombHandsRig : MonoBehaviour
    {
        [Tooltip("Rigidbodies with a box or sphere collider the hands can touch.")]
        public Rigidbody[] bodies = new Rigidbody[0];
        [Tooltip("The skin-object material of every body: wood, glass, paper, ...")]
        public string material = "wood";

        private Rig rig;
        private XRHandSubsystem hands;
        private readonly float[][] joints = { new float[78], new float[78] };
        private readonly float[][] radii = { new float[26], new float[26] };
        private HostBody[] states;
        private Rigidbody[] touched; // the bodies the rig has, in its order

        void Start()
        {
            rig = new Rig(Time.fixedDeltaTime);
            foreach (var body in bodies)
            {
                Vector3 p = body.position, s = body.transform.lossyScale;
                Quaternion q = body.rotation;
                var box = body.GetComponent<BoxCollider>();
                if (box != null)
                {
                    if (box.center != Vector3.zero)
                        Debug.LogWarning(body.name + ": the box is taken as centred on its body");
                    var size = Vector3.Scale(box.size, s);
                    rig.AddBox(body.name, new Vec3(size.x, size.y, size.z), body.mass,
                               new Vec3(p.x, p.y, p.z), new Quat(q.x, q.y, q.z, q.w), material);
                    continue;
                }
                var ball = body.GetComponent<SphereCollider>();
                if (ball == null)
                {
                    Debug.LogWarning(body.name + ": no box or sphere collider; the hands ignore it");
                    continue;
                }
                float radius = ball.radius * Mathf.Max(s.x, Mathf.Max(s.y, s.z));
                rig.AddSphere(body.name, radius, body.mass, new Vec3(p.x, p.y, p.z), material);
            }
            touched = System.Array.FindAll(bodies, b =>
                b.GetComponent<BoxCollider>() != null || b.GetComponent<SphereCollider>() != null);
            states = new HostBody[touched.Length];
        }

        void FixedUpdate()
        {
            if (hands == null || !hands.running) hands = FindHands();
            SetHand(0, hands == null ? default(XRHand) : hands.leftHand);
            SetHand(1, hands == null ? default(XRHand) : hands.rightHand);
            for (int i = 0; i < touched.Length; i++) states[i] = State(touched[i]);
            var wrenches = rig.Step(states);
            for (int i = 0; i < wrenches.Length; i++)
            {
                var w = wrenches[i];
                if (w.Pushed == 0) continue;
                var body = touched[(int)w.Object];
                body.AddForce(new Vector3(w.ForceX, w.ForceY, w.ForceZ), ForceMode.Force);
                body.AddTorque(new Vector3(w.TorqueX, w.TorqueY, w.TorqueZ), ForceMode.Force);
            }
        }

        void OnDestroy()
        {
            if (rig != null) rig.Dispose();
        }

        private void SetHand(int side, XRHand hand)
        {
            if (!hand.isTracked)
            {
                rig.SetHand(side, null, null);
                return;
            }
            var origin = transform; // the XR Origin's tracking space
            for (int j = 0; j < 26; j++)
            {
                var joint = hand.GetJoint(XRHandJointIDUtility.FromIndex(j));
                Pose pose;
                float radius;
                if (!joint.TryGetPose(out pose))
                {
                    rig.SetHand(side, null, null); // a joint lost: the hand is not tracked
                    return;
                }
                if (!joint.TryGetRadius(out radius)) radius = 0.008f;
                var p = origin.TransformPoint(pose.position);
                joints[side][3 * j] = p.x;
                joints[side][3 * j + 1] = p.y;
                joints[side][3 * j + 2] = p.z;
                radii[side][j] = radius;
            }
            rig.SetHand(side, joints[side], radii[side]);
        }

        private static HostBody State(Rigidbody b)
        {
            Vector3 p = b.position, v = b.velocity, w = b.angularVelocity, c = b.centerOfMass;
            Vector3 i = b.inertiaTensor;
            Quaternion q = b.rotation, iq = b.inertiaTensorRotation;
            return new HostBody
            {
                PositionX = p.x, PositionY = p.y, PositionZ = p.z,
                RotationX = q.x, RotationY = q.y, RotationZ = q.z, RotationW = q.w,
                LinvelX = v.x, LinvelY = v.y, LinvelZ = v.z,
                AngvelX = w.x, AngvelY = w.y, AngvelZ = w.z,
                Mass = b.mass,
                CenterOfMassX = c.x, CenterOfMassY = c.y, CenterOfMassZ = c.z,
                InertiaX = i.x, InertiaY = i.y, InertiaZ = i.z,
                InertiaRotationX = iq.x, InertiaRotationY = iq.y, InertiaRotationZ = iq.z,
                InertiaRotationW = iq.w,
            };
        }

        private static XRHandSubsystem FindHands()
        {
            var found = new System.Collections.Generic.List<XRHandSubsystem>();
            SubsystemManager.GetSubsystems(found);
            return found.Count > 0 ? found[0] : null;
        }
    }
}
