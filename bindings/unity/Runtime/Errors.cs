// A failed call as a typed exception: one per status, with the library's message, which
// names the call and the argument.
using System;

namespace CoulombHands
{
    /// <summary>A call the library refused; <see cref="Status"/> says which kind.</summary>
    public class CoulombHandsException : Exception
    {
        public Status Status { get; private set; }

        public CoulombHandsException(Status status, string message) : base(message)
        {
            Status = status;
        }

        /// <summary>The exception for a status and the thread's last error.</summary>
        public static CoulombHandsException Of(Status status, string message)
        {
            switch (status)
            {
                case Status.NullPointer: return new NullArgumentException(message);
                case Status.InvalidArgument: return new InvalidArgumentException(message);
                case Status.BufferTooSmall: return new BufferTooSmallException(message);
                case Status.StaleHandle: return new StaleHandleException(message);
                case Status.InvalidInput: return new InvalidInputException(message);
                case Status.Refused: return new RefusedException(message);
                case Status.AbiMismatch: return new AbiMismatchException(message);
                default: return new InternalException(status, message);
            }
        }
    }

    /// <summary>A required argument was null.</summary>
    public sealed class NullArgumentException : CoulombHandsException
    {
        public NullArgumentException(string m) : base(Status.NullPointer, m) { }
    }

    /// <summary>A wrong length, a number that is not finite, an unknown name.</summary>
    public sealed class InvalidArgumentException : CoulombHandsException
    {
        public InvalidArgumentException(string m) : base(Status.InvalidArgument, m) { }
    }

    /// <summary>An output array too short.</summary>
    public sealed class BufferTooSmallException : CoulombHandsException
    {
        public BufferTooSmallException(string m) : base(Status.BufferTooSmall, m) { }
    }

    /// <summary>A world used after it was disposed.</summary>
    public sealed class StaleHandleException : CoulombHandsException
    {
        public StaleHandleException(string m) : base(Status.StaleHandle, m) { }
    }

    /// <summary>A config, scene or recording refused (its JSON, a field, a value).</summary>
    public sealed class InvalidInputException : CoulombHandsException
    {
        public InvalidInputException(string m) : base(Status.InvalidInput, m) { }
    }

    /// <summary>The world refused the call (an unknown id, a state it cannot take).</summary>
    public sealed class RefusedException : CoulombHandsException
    {
        public RefusedException(string m) : base(Status.Refused, m) { }
    }

    /// <summary>The native library is of another ABI version than this package.</summary>
    public sealed class AbiMismatchException : CoulombHandsException
    {
        public AbiMismatchException(string m) : base(Status.AbiMismatch, m) { }
    }

    /// <summary>A fault inside the library; dispose the world.</summary>
    public sealed class InternalException : CoulombHandsException
    {
        public InternalException(Status s, string m) : base(s, m) { }
    }
}
